// Box2D 2.4.1's profiling timer, replaced by one that reads no clock.
//
// Why: b2World::Step times itself for b2World::GetProfile() with b2Timer, which calls
// gettimeofday() seven times per island per sub-step (b2Island::Solve) — and every free
// robot is its own island (its servo joint ties it only to its own kinematic body). At
// 1000 robots and 10 sub-steps that is 70 000 clock reads per tick, ~7% of a whole
// avoidance-1000 run. essaim never reads the profile, and no other Box2D result depends
// on the timer (it only fills b2Profile and b2_toiTime statistics), so the simulation is
// bit-for-bit the same.
//
// How: libbox2d.so calls its b2Timer members through the PLT, so a definition in the
// program interposes on them (ELF symbol interposition, as a malloc replacement does).
// Only Box2D's own timer changes; the process's clocks (gettimeofday, std::chrono) are
// untouched. The library's CMake target forces this object into every binary that links
// essaim_physics (it is otherwise unreferenced). Not patching or vendoring Box2D keeps
// Debian's libbox2d as it is; tests/physics/box2d_profile_timer_test.cpp checks the replacement
// is live.
#include <box2d/b2_timer.h>

b2Timer::b2Timer() { Reset(); }

void b2Timer::Reset() {
  m_start_sec = 0;
  m_start_usec = 0;
}

float b2Timer::GetMilliseconds() const { return 0.0f; }
