// Umbrella header for Tidewater's CPU model (Tidewater::core).
#pragma once

#include "tidewater/clock.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/floating_body.hpp"
#include "tidewater/gerstner.hpp"
#include "tidewater/query.hpp"
#include "tidewater/result.hpp"
#include "tidewater/ripples.hpp"
#include "tidewater/scene.hpp"
#include "tidewater/scene_bake.hpp"
#include "tidewater/spectrum.hpp"
#include "tidewater/terrain.hpp"
#include "tidewater/version.hpp"
#include "tidewater/water_body.hpp"
#include "tidewater/waves.hpp"
#include "tidewater/world_query.hpp"
#include "tidewater/drift.hpp"
