// The interactive inspector: the warped surface coloured by a field with its legend,
// the terrain and the shoreline, velocity glyphs, a time slider with play/pause, a
// field selector and a click-to-probe chart.
//
// Keys (besides VTK's usual mouse camera): space play/pause, f next field,
// g glyphs on/off (the current under the flow field, else the velocity), p probe the point under the mouse (shows its
// chart in a window, writes it to probe_X_Z.png and prints the dominant period), r reset the camera, q quit. Threading:
// one viewer per thread; VTK windows need a display (xvfb-run without one).
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "field_sampler.hpp"

namespace tidewater::inspect {

class Viewer {
  public:
    /// Samples `times.front()`; fails on a bad grid or field.
    static Result<std::unique_ptr<Viewer>> create(const Scene& scene, const SampleGrid& grid, std::vector<double> times,
                                                  const std::string& field, int width, int height, bool offscreen);
    ~Viewer();

    Status set_time_index(std::size_t index);  ///< Resamples the water at times[index].
    void next_field();                         ///< Colours by the next field (f).
    void set_glyphs(bool on);                  ///< Arrows (g): the current when the field is flow, else the velocity.
    /// A path (x, z) drawn as a line on the water at the shown time, such as a drift track.
    void set_track(const std::vector<glm::dvec2>& path);
    /// Charts the height at (x, z) over the viewer's times to `png`; returns the dominant period.
    Result<double> probe(glm::dvec2 at, const std::filesystem::path& png);
    Status save(const std::filesystem::path& png);  ///< The current view, as drawn.
    void render();                                  ///< Draws the current view.
    std::string field() const;
    double time() const;
    /// Opens the window and runs until it is closed.
    void run();

  private:
    struct Impl;
    explicit Viewer(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace tidewater::inspect
