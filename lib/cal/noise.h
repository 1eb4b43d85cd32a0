// Procedural noise for textures: the character of Radiance's noise3, noise3x/y/z, fnoise3 and rand, not
// their exact values (Radiance's lattice tables are its own).
#pragma once
#include <array>

namespace brume::cal {

// Gradient noise after Perlin, "Improving Noise" (SIGGRAPH 2002): quintic fade, the 12 cube-edge
// gradients on the unit integer lattice; zero at lattice points, values in about [-1, 1].
double perlinNoise(double x, double y, double z);
// The same noise with its exact gradient {value, d/dx, d/dy, d/dz} (Radiance's noise3x/y/z are
// finite differences of noise3).
std::array<double, 4> perlinNoiseAndGradient(double x, double y, double z);

// Fractal (1/f) noise, mostly within [-1, 1] like Radiance's: eleven octaves of value noise, each twice
// the frequency and half the amplitude of the last, from the unit lattice down to about Radiance's
// 0.0005 resolution.
double fractalNoise(double x, double y, double z);

// A pseudo-random number in [0, 1) that depends only on x (Radiance's rand(x)).
double hashRandom(double x);

}  // namespace brume::cal
