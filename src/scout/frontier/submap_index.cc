#include "scout/frontier/submap_index.h"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <unordered_map>

namespace scout::frontier {
namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BgPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using BgBox = bg::model::box<BgPoint>;
using Value = std::pair<BgBox, int>;

BgBox ToBg(const geometry::Box2d& b) {
  return BgBox(BgPoint(b.min.x(), b.min.y()), BgPoint(b.max.x(), b.max.y()));
}

}  // namespace

struct SubmapIndex::Impl {
  bgi::rtree<Value, bgi::rstar<16>> tree;
  std::unordered_map<int, BgBox> boxes;
};

SubmapIndex::SubmapIndex() : impl_(std::make_unique<Impl>()) {}
SubmapIndex::~SubmapIndex() = default;
SubmapIndex::SubmapIndex(SubmapIndex&&) noexcept = default;
SubmapIndex& SubmapIndex::operator=(SubmapIndex&&) noexcept = default;

void SubmapIndex::Set(int id, const geometry::Box2d& box) {
  const auto it = impl_->boxes.find(id);
  if (it != impl_->boxes.end()) {
    impl_->tree.remove(Value(it->second, id));
    impl_->boxes.erase(it);
  }
  if (box.empty()) return;
  const BgBox bg_box = ToBg(box);
  impl_->tree.insert(Value(bg_box, id));
  impl_->boxes.emplace(id, bg_box);
}

void SubmapIndex::AppendContaining(const Eigen::Vector2d& p, std::vector<int>* out) const {
  // 'intersects' with a point is closed-box containment.
  const BgPoint q(p.x(), p.y());
  for (auto it = impl_->tree.qbegin(bgi::intersects(q)); it != impl_->tree.qend(); ++it) {
    out->push_back(it->second);
  }
}

std::vector<int> SubmapIndex::Containing(const Eigen::Vector2d& p) const {
  std::vector<int> ids;
  AppendContaining(p, &ids);
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::vector<int> SubmapIndex::Intersecting(const geometry::Box2d& box) const {
  std::vector<int> ids;
  if (box.empty()) return ids;
  for (auto it = impl_->tree.qbegin(bgi::intersects(ToBg(box))); it != impl_->tree.qend(); ++it) {
    ids.push_back(it->second);
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

size_t SubmapIndex::size() const { return impl_->tree.size(); }

}  // namespace scout::frontier
