// What the water stages of one draw share: the draw's description (the ocean, a lake
// or a river), the rivers' fields and waves and the patch list (the rivers' and lakes'
// masks are body_masks.glsl's).
// Set kFrameSet, bindings eFrameRiverTexels to eFrameWakePoints (host_device.h; the draws
// themselves are frame.glsl's); the push constant at kPushDrawIndex picks the draw.
#ifndef TIDEWATER_WATER_DRAW_GLSL
#define TIDEWATER_WATER_DRAW_GLSL

layout(std430, set = kFrameSet, binding = eFrameRiverTexels) readonly buffer RiverTexels { float river_texels[]; };   // kRiverQueryStride per texel
layout(std430, set = kFrameSet, binding = eFrameRiverChannel) readonly buffer RiverChannel { vec4 river_channel[]; };  // s, n (m), flow x, z (m/s)
layout(std430, set = kFrameSet, binding = eFrameRiverWaves) readonly buffer RiverWaves { GpuRiverWave river_waves[]; };
layout(std430, set = kFrameSet, binding = eFramePatchList) readonly buffer PatchList { uint patch_list[]; };       // x | z << 16
layout(std430, set = kFrameSet, binding = eFrameWakePoints) readonly buffer WakePoints { vec4 wake_blocks[kMaxWakeBlocks]; GpuWakePoint wake_points[]; };  // chains in order, relative to O
layout(push_constant) uniform DrawPush { layout(offset = kPushDrawIndex) uint draw_index; } draw_push;

// The draw whose river fields river_water.glsl reads (set before evaluating).
GpuBodyDraw g_draw;

#define RIVER_NX uint(g_draw.river.x)
#define RIVER_NZ uint(g_draw.river.y)
#define RIVER_TEXEL g_draw.grid.z
#define RIVER_FIRST_TEXEL uint(g_draw.grid.w)
#define RIVER_FIRST_WAVE uint(g_draw.river.z)
#define RIVER_WAVE_COUNT uint(g_draw.river.w)
#define RIVER_BANK_RAMP g_draw.rivers.w


// Whether rest position xz (relative to O) lies where the frame's wakes can be felt
// (GpuFrame.wake_boxes): elsewhere their contributions cancel and are not summed. A
// function of the position alone, so neighbouring patches agree on shared vertices.
bool wakes_reach(vec2 xz) {
    for (uint b = 0u; b < uint(frame.wakes.z); ++b) {
        vec4 box = frame.wake_boxes[b];
        if (all(greaterThanEqual(xz, box.xy)) && all(lessThanEqual(xz, box.zw))) return true;
    }
    return false;
}
#endif
