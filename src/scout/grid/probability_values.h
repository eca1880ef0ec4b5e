#ifndef SCOUT_GRID_PROBABILITY_VALUES_H_
#define SCOUT_GRID_PROBABILITY_VALUES_H_

#include <cstdint>
#include <vector>

namespace scout::grid {

// Probabilities are stored as 15-bit values: 0 means "never observed"
// (unknown); 1..32767 map linearly onto [kMinProbability, kMaxProbability].
// Bit 15 (kUpdateMarker) marks a cell already updated by the current scan.
inline constexpr float kMinProbability = 0.1f;
inline constexpr float kMaxProbability = 0.9f;
inline constexpr uint16_t kUnknownValue = 0;
inline constexpr uint16_t kMaxValue = 32767;
inline constexpr uint16_t kUpdateMarker = 1u << 15;

namespace internal {
// The linear map is anchored at its midpoint, in double, with the exact decimal
// bounds 0.1 / 0.9: then value 1, kMidValue and kMaxValue decode to exactly
// kMinProbability, 0.5f and kMaxProbability, so "p == 0.5 is unknown" (ALGORITHMS §1)
// is reachable and the clamps are hit exactly after repeated updates.
inline constexpr double kMinProbabilityExact = 0.1;
inline constexpr double kMaxProbabilityExact = 0.9;
static_assert(static_cast<float>(kMinProbabilityExact) == kMinProbability);
static_assert(static_cast<float>(kMaxProbabilityExact) == kMaxProbability);
inline constexpr int kMidValue = (1 + kMaxValue) / 2;  // 16384 decodes to 0.5
inline constexpr double kProbabilityPerValue =
    (kMaxProbabilityExact - kMinProbabilityExact) / (kMaxValue - 1);
}  // namespace internal

// Returns the value for probability 'p', clamped to [kMinProbability, kMaxProbability].
uint16_t ProbabilityToValue(float p);
// Returns the probability of a known value (1..32767); 0.5 for kUnknownValue.
// Inline: scan matching decodes sixteen cells per point and iteration.
inline float ValueToProbability(uint16_t value) {
  // Tolerate a value that still carries the update marker.
  const int v = value & kMaxValue;
  if (v == kUnknownValue) return 0.5f;
  return static_cast<float>(0.5 + (v - internal::kMidValue) * internal::kProbabilityPerValue);
}

inline float Odds(float p) { return p / (1.f - p); }
inline float ProbabilityFromOdds(float odds) { return odds / (1.f + odds); }

// Returns the table that maps every value v (with and without the update
// marker) to the value after one observation with odds 'odds'; an unknown cell
// takes the observation's probability. Results carry kUpdateMarker, so a cell
// is changed at most once per scan (entries for already-marked inputs are the
// identity).
std::vector<uint16_t> ComputeLookupTableToApplyOdds(float odds);

}  // namespace scout::grid

#endif  // SCOUT_GRID_PROBABILITY_VALUES_H_
