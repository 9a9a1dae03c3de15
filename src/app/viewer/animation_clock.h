// The viewer's animation time: play, pause, scrub and loop, advanced by wall-clock time.
#pragma once

namespace wp {

// The time at which the viewer poses an animated scene, in seconds in [0, duration].
class AnimationClock {
public:
  // Paused at `start`, clamped to [0, duration]. Requires duration > 0.
  AnimationClock(double duration, double start);

  double time() const { return time_; }
  double duration() const { return duration_; }
  bool playing() const { return playing_; }
  bool loop() const { return loop_; }
  double speed() const { return speed_; }

  // Playing from the end without loop starts again at 0, as media players do.
  void play();
  void pause() { playing_ = false; }
  void toggle();
  void setLoop(bool loop) { loop_ = loop; }
  // Animation seconds per wall-clock second. Requires speed > 0.
  void setSpeed(double speed) { speed_ = speed; }

  // Moves the time on by `seconds` of wall-clock time times the speed, while playing. Past
  // the end it wraps to the start with loop; without, it stops at the end and pauses.
  void advance(double seconds);
  // Jumps to `time` clamped to [0, duration]; playing goes on from there.
  void scrub(double time);

private:
  double duration_;
  double time_;
  bool playing_ = false;
  bool loop_ = false;
  double speed_ = 1.0;
};

}  // namespace wp
