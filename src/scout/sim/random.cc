#include "scout/sim/random.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace scout::sim {

double UniformUnit(std::mt19937_64& rng) {
  constexpr double kTwoToMinus53 = 1.0 / 9007199254740992.0;
  return static_cast<double>(rng() >> 11) * kTwoToMinus53;
}

double UniformReal(std::mt19937_64& rng, double min, double max) {
  const double u = UniformUnit(rng);
  return max <= min ? min : min + u * (max - min);
}

int UniformInt(std::mt19937_64& rng, int min, int max) {
  const double u = UniformUnit(rng);
  if (max <= min) return min;
  const int64_t span = static_cast<int64_t>(max) - min + 1;
  const int64_t offset = std::min<int64_t>(static_cast<int64_t>(u * span), span - 1);
  return static_cast<int>(min + offset);
}

bool Bernoulli(std::mt19937_64& rng, double probability) { return UniformUnit(rng) < probability; }

double StandardNormal(std::mt19937_64& rng) {
  // 1 - u lies in (0, 1], so the logarithm is finite.
  const double u1 = 1.0 - UniformUnit(rng);
  const double u2 = UniformUnit(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

uint64_t DeriveSeed(uint64_t seed, uint64_t stream) {
  uint64_t z = seed + (stream + 1) * 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace scout::sim
