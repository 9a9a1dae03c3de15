// The viewer's playback clock without a window: play and pause, wall-clock advance at a
// speed, loop or stop at the end, scrubbing within the animation.
#include <gtest/gtest.h>

#include "app/viewer/animation_clock.h"

namespace wp {
namespace {

// Sums of a few binary fractions and one fmod: exact up to ~1e-15, far below the steps the
// tests take (>= 0.1 s).
constexpr double kTol = 1e-12;

TEST(AnimationClock, StartsPausedAtTheStartTimeClamped) {
  EXPECT_DOUBLE_EQ(AnimationClock(2.0, 0.5).time(), 0.5);
  EXPECT_FALSE(AnimationClock(2.0, 0.5).playing());
  EXPECT_DOUBLE_EQ(AnimationClock(2.0, 7.0).time(), 2.0);
  EXPECT_DOUBLE_EQ(AnimationClock(2.0, -1.0).time(), 0.0);
}

TEST(AnimationClock, PausedDoesNotAdvance) {
  AnimationClock clock(2.0, 0.5);
  clock.advance(0.25);
  EXPECT_DOUBLE_EQ(clock.time(), 0.5);
  clock.toggle();
  EXPECT_TRUE(clock.playing());
  clock.toggle();
  EXPECT_FALSE(clock.playing());
  clock.advance(0.25);
  EXPECT_DOUBLE_EQ(clock.time(), 0.5);
}

TEST(AnimationClock, PlayingAdvancesByWallClockTimesSpeed) {
  AnimationClock clock(2.0, 0.5);
  clock.play();
  clock.advance(0.25);
  EXPECT_NEAR(clock.time(), 0.75, kTol);
  clock.setSpeed(2.0);
  clock.advance(0.25);
  EXPECT_NEAR(clock.time(), 1.25, kTol);
  EXPECT_TRUE(clock.playing());
}

TEST(AnimationClock, WithLoopItWrapsToTheStart) {
  AnimationClock clock(2.0, 1.5);
  clock.setLoop(true);
  clock.play();
  clock.advance(0.75);
  EXPECT_NEAR(clock.time(), 0.25, kTol);
  EXPECT_TRUE(clock.playing());
  clock.advance(4.5);  // more than a whole loop in one frame
  EXPECT_NEAR(clock.time(), 0.75, kTol);
}

TEST(AnimationClock, WithoutLoopItStopsAtTheEndAndPlaysAgainFromTheStart) {
  AnimationClock clock(2.0, 1.5);
  clock.play();
  clock.advance(0.75);
  EXPECT_DOUBLE_EQ(clock.time(), 2.0);
  EXPECT_FALSE(clock.playing());
  clock.advance(0.75);
  EXPECT_DOUBLE_EQ(clock.time(), 2.0);
  clock.play();
  EXPECT_DOUBLE_EQ(clock.time(), 0.0);
  EXPECT_TRUE(clock.playing());
}

TEST(AnimationClock, ScrubClampsToTheAnimation) {
  AnimationClock clock(2.0, 0.0);
  clock.scrub(1.25);
  EXPECT_DOUBLE_EQ(clock.time(), 1.25);
  clock.scrub(3.0);
  EXPECT_DOUBLE_EQ(clock.time(), 2.0);
  clock.scrub(-0.5);
  EXPECT_DOUBLE_EQ(clock.time(), 0.0);
  // Playing goes on from where the scrub left it.
  clock.play();
  clock.scrub(1.0);
  clock.advance(0.5);
  EXPECT_NEAR(clock.time(), 1.5, kTol);
}

}  // namespace
}  // namespace wp
