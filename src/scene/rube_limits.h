// The ranges of RUBE scene values, shared by the reader and the joint table.
//
// They keep Box2D and the effects finite and their cost bounded, generous for real scenes (the real RUBE
// samples use friction up to 100, restitution up to 0.8, masses up to 190 kg). docs/rube.md lists them.
#pragma once

#include "scene/json_reader.h"

namespace cfx::scene_detail
{

inline constexpr NumberLimits kStepRate{0.0, 1.0e4, true}; // Hz
inline constexpr NumberLimits kUnit{0.0, 1.0, false};
inline constexpr NumberLimits kGravity{-1.0e4, 1.0e4, false}; // m/s^2 per axis (1,000 g)
inline constexpr NumberLimits kSpeed{-1.0e4, 1.0e4, false};   // m/s or rad/s
inline constexpr NumberLimits kGravityScale{-1.0e3, 1.0e3, false};
inline constexpr NumberLimits kDamping{0.0, 1.0e3, false}; // 1/s
inline constexpr NumberLimits kFriction{0.0, 1.0e3, false};
inline constexpr NumberLimits kRestitution{0.0, 10.0, false}; // > 1 gains energy, as Box2D allows
inline constexpr NumberLimits kDensity{0.0, 1.0e6, false};    // kg/m^2
inline constexpr NumberLimits kMass{0.0, 1.0e12, false};      // kg
inline constexpr NumberLimits kInertia{0.0, 1.0e24, false};   // kg m^2
inline constexpr NumberLimits kForce{0.0, 1.0e12, false};     // N or N m
inline constexpr NumberLimits kFrequency{0.0, 1.0e4, false};  // Hz
inline constexpr NumberLimits kDampingRatio{0.0, 1.0e3, false};
inline constexpr NumberLimits kPulleyRatio{0.0, 1.0e3, true};
inline constexpr NumberLimits kGearRatio{-1.0e3, 1.0e3, false};
inline constexpr NumberLimits kImageScale{-1.0e6, 1.0e6, false};
inline constexpr int kMaxIterations = 1000;

} // namespace cfx::scene_detail
