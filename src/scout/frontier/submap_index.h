#ifndef SCOUT_FRONTIER_SUBMAP_INDEX_H_
#define SCOUT_FRONTIER_SUBMAP_INDEX_H_

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "scout/geometry/box.h"

namespace scout::frontier {

// An R-tree (Boost.Geometry, R*-tree) over the global bounding boxes of
// submaps, keyed by submap id.
class SubmapIndex {
 public:
  SubmapIndex();
  ~SubmapIndex();
  SubmapIndex(SubmapIndex&&) noexcept;
  SubmapIndex& operator=(SubmapIndex&&) noexcept;

  // Inserts or replaces the box of submap 'id'.
  void Set(int id, const geometry::Box2d& box);
  // Returns the ids whose box contains 'p' (closed boxes), ascending.
  std::vector<int> Containing(const Eigen::Vector2d& p) const;
  // Appends to 'out' the ids whose box contains 'p', unsorted. Cheaper in loops.
  void AppendContaining(const Eigen::Vector2d& p, std::vector<int>* out) const;
  // Returns the ids whose box intersects 'box', ascending.
  std::vector<int> Intersecting(const geometry::Box2d& box) const;
  size_t size() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace scout::frontier

#endif  // SCOUT_FRONTIER_SUBMAP_INDEX_H_
