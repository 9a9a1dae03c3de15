// The brightest radiance and the farthest coordinate a scene may hold, so that no sum or
// product on the GPU overflows.
#pragma once

namespace wp {

// The brightest emission or sky radiance (per channel) wavepath accepts from a file or a
// flag: 1e12, some 600 times the sun's disk (1.6e9 cd/m^2). Each pixel sums its samples and
// their squares in 32-bit floats; a sample is radiance times the path's throughput over its
// pdf, often several times the radiance, and the square of a sample above about 1e19 is
// infinite, which makes the pixel's variance NaN. Brighter inputs are refused, not clamped,
// so that no picture is silently wrong.
inline constexpr double kMaxRadiance = 1e12;

// The farthest coordinate (scene units) a vertex, keyframe or placed object may have: 1e12,
// some 7 times the distance to the sun in metres. Ray tracing multiplies coordinates (cross
// products of edges, squared distances, areas times radiance): beyond about 1e18 those
// overflow single precision, and long before it nothing but noise is left of the geometry.
inline constexpr double kMaxCoordinate = 1e12;

}  // namespace wp
