#include "scout/grid/probability_values.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace scout::grid {
namespace {

using internal::kMidValue;
using internal::kProbabilityPerValue;

}  // namespace

uint16_t ProbabilityToValue(float p) {
  // NaN carries no information about the cell; treat it as the no-information 0.5.
  const double clamped =
      std::isnan(p) ? 0.5
                    : std::clamp(static_cast<double>(p), static_cast<double>(kMinProbability),
                                 static_cast<double>(kMaxProbability));
  const long value = kMidValue + std::lround((clamped - 0.5) / kProbabilityPerValue);
  return static_cast<uint16_t>(std::clamp<long>(value, 1, kMaxValue));
}

std::vector<uint16_t> ComputeLookupTableToApplyOdds(float odds) {
  if (!(odds > 0.f) || !std::isfinite(odds)) {
    throw std::invalid_argument("ComputeLookupTableToApplyOdds: odds must be positive and finite");
  }
  // Indexed by the raw stored value: the lower half holds cells not yet updated
  // in this scan, the upper half (kUpdateMarker set) those already updated.
  std::vector<uint16_t> table(2 * static_cast<size_t>(kUpdateMarker));
  table[kUnknownValue] = ProbabilityToValue(ProbabilityFromOdds(odds)) | kUpdateMarker;
  for (int v = 1; v <= kMaxValue; ++v) {
    const float updated = ProbabilityFromOdds(odds * Odds(ValueToProbability(v)));
    table[v] = ProbabilityToValue(updated) | kUpdateMarker;
  }
  for (size_t v = kUpdateMarker; v < table.size(); ++v) table[v] = static_cast<uint16_t>(v);
  return table;
}

}  // namespace scout::grid
