#ifndef SCOUT_SIM_RANDOM_H_
#define SCOUT_SIM_RANDOM_H_

#include <cstdint>
#include <random>

// Portable random variates: std::mt19937_64 is specified bit-exactly by the
// standard, but std::*_distribution are not, so Scout draws through these to
// stay deterministic across standard libraries.
namespace scout::sim {

// Returns a uniform double in [0, 1) from the top 53 bits of one draw.
double UniformUnit(std::mt19937_64& rng);

// Returns a uniform double in [min, max) (min when max <= min).
double UniformReal(std::mt19937_64& rng, double min, double max);

// Returns a uniform integer in [min, max], both inclusive (min when max <= min).
int UniformInt(std::mt19937_64& rng, int min, int max);

// Returns true with probability 'probability'.
bool Bernoulli(std::mt19937_64& rng, double probability);

// Returns a standard normal variate (Box-Muller; always consumes two draws).
double StandardNormal(std::mt19937_64& rng);

// Returns a seed for the independent stream 'stream' of 'seed' (SplitMix64),
// so that e.g. lidar noise and pose drift do not share one sequence.
uint64_t DeriveSeed(uint64_t seed, uint64_t stream);

}  // namespace scout::sim

#endif  // SCOUT_SIM_RANDOM_H_
