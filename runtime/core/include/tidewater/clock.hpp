// Simulation clock: time in double seconds, pause/resume and time scale.
//
// The host advances the clock with real frame times; queries and rendering
// read now(). A water body adds its own offset (WaterBody::time_offset).
// Threading: not synchronised; own one per simulation and read it from the
// thread that advances it (pass the time value to worker threads).
#pragma once

namespace tidewater {

class Clock {
  public:
    explicit Clock(double start_time = 0.0) : time_(start_time) {}

    /// Advances by `real_seconds` times the scale, unless paused. Negative or
    /// non-finite steps are ignored (a hitch must not rewind the sea).
    void advance(double real_seconds);
    void pause() { paused_ = true; }
    void resume() { paused_ = false; }
    bool paused() const { return paused_; }

    /// Multiplier on real time; 0 freezes, 2 plays double speed. Must be finite and >= 0.
    bool set_scale(double scale);
    double scale() const { return scale_; }

    void set_time(double seconds) { time_ = seconds; }
    double now() const { return time_; }

  private:
    double time_ = 0.0;
    double scale_ = 1.0;
    bool paused_ = false;
};

}  // namespace tidewater
