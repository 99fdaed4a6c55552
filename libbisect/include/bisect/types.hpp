// Basic value types shared by every stage.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products on Vec3
#include <cstdint>

namespace bisect {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
// Indices into flat arrays are 32-bit (ARCHITECTURE.md §5): 2^31 nodes or tetrahedra is far
// beyond what one process meshes, and half the memory traffic of 64-bit indices.
using Index = std::int32_t;

}  // namespace bisect
