#pragma once
// A force and a torque on one body, world frame; the torque is about the centre of mass X.
#include "engine/core/vec3.hpp"

namespace washout::rigid {

struct BodyLoad {
  Vec3 force = Vec3::Zero();   // [N]
  Vec3 torque = Vec3::Zero();  // [N m], about X

  BodyLoad& operator+=(const BodyLoad& other) {
    force += other.force;
    torque += other.torque;
    return *this;
  }
  friend BodyLoad operator+(BodyLoad a, const BodyLoad& b) { return a += b; }
};

}  // namespace washout::rigid
