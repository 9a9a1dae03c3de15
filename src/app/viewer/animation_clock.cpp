// Playback time of the viewer, free of any window so it is tested directly.
#include "app/viewer/animation_clock.h"

#include <algorithm>
#include <cmath>

namespace wp {

AnimationClock::AnimationClock(double duration, double start)
    : duration_(duration), time_(std::clamp(start, 0.0, duration)) {}

void AnimationClock::play() {
  if (!loop_ && time_ >= duration_) time_ = 0.0;
  playing_ = true;
}

void AnimationClock::toggle() {
  if (playing_) {
    pause();
  } else {
    play();
  }
}

void AnimationClock::advance(double seconds) {
  if (!playing_) return;
  double next = time_ + seconds * speed_;
  if (next < duration_) {
    time_ = next;
  } else if (loop_) {
    time_ = std::fmod(next, duration_);
  } else {
    time_ = duration_;
    playing_ = false;
  }
}

void AnimationClock::scrub(double time) { time_ = std::clamp(time, 0.0, duration_); }

}  // namespace wp
