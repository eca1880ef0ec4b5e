#include "scout/io/slam_summary.h"

namespace scout::io {

nlohmann::json SlamSummary(const slam::SlamStats& stats, bool synchronous) {
  return {{"nodes", stats.num_nodes},
          {"submaps", stats.num_submaps},
          {"optimizations", stats.num_optimizations},
          {"loop_closures", stats.num_loop_closures},
          {"rejected_loop_closures", stats.num_rejected_loop_closures},
          {"gated_loop_closures", stats.num_gated_loop_closures},
          {"loop_closure_searches", stats.num_loop_closure_searches},
          {"searches_without_match", stats.num_searches_without_match},
          {"ambiguous_matches", stats.num_ambiguous_matches},
          {"wide_ambiguous_matches", stats.num_wide_ambiguous_matches},
          {"matches_seeing_through", stats.num_matches_seeing_through},
          {"pairs_without_overlap", stats.num_pairs_without_overlap},
          {"near_matches", stats.num_near_matches},
          {"solve_time_s", stats.total_solve_time_s},
          {"synchronous", synchronous}};
}

}  // namespace scout::io
