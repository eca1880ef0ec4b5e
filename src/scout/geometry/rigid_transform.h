#ifndef SCOUT_GEOMETRY_RIGID_TRANSFORM_H_
#define SCOUT_GEOMETRY_RIGID_TRANSFORM_H_

#include <Eigen/Core>
#include <cmath>
#include <ostream>
#include <vector>

namespace scout::geometry {

// Returns 'angle_rad' wrapped into [-pi, pi).
double NormalizeAngle(double angle_rad);

// A rigid 2D transform (rotation by theta, then translation). As a pose it
// maps points of the child frame into the parent frame: p_parent = T * p_child.
class Rigid2d {
 public:
  Rigid2d() = default;
  Rigid2d(double x_m, double y_m, double theta_rad)
      : Rigid2d(Eigen::Vector2d(x_m, y_m), theta_rad) {}
  Rigid2d(const Eigen::Vector2d& translation, double theta_rad)
      : translation_(translation),
        theta_(NormalizeAngle(theta_rad)),
        cos_(std::cos(theta_)),
        sin_(std::sin(theta_)) {}

  static Rigid2d Identity() { return Rigid2d(); }

  const Eigen::Vector2d& translation() const { return translation_; }
  double x() const { return translation_.x(); }
  double y() const { return translation_.y(); }
  // Rotation angle in [-pi, pi).
  double theta() const { return theta_; }

  // Returns the rotated-only image of 'v' (no translation).
  Eigen::Vector2d Rotate(const Eigen::Vector2d& v) const {
    return {cos_ * v.x() - sin_ * v.y(), sin_ * v.x() + cos_ * v.y()};
  }

  // Returns T * p.
  Eigen::Vector2d operator*(const Eigen::Vector2d& p) const { return Rotate(p) + translation_; }

  // Returns the composition this * other (apply 'other' first).
  Rigid2d operator*(const Rigid2d& other) const {
    // Angle addition instead of cos/sin of the summed angle: no trigonometry.
    return Rigid2d(Rotate(other.translation_) + translation_, NormalizeAngle(theta_ + other.theta_),
                   cos_ * other.cos_ - sin_ * other.sin_, sin_ * other.cos_ + cos_ * other.sin_);
  }

  // Returns T^-1.
  Rigid2d inverse() const {
    const Eigen::Vector2d back(cos_ * translation_.x() + sin_ * translation_.y(),
                               -sin_ * translation_.x() + cos_ * translation_.y());
    return Rigid2d(-back, NormalizeAngle(-theta_), cos_, -sin_);
  }

 private:
  // For results whose cos/sin follow from their operands'.
  Rigid2d(const Eigen::Vector2d& translation, double normalized_theta_rad, double cos_theta,
          double sin_theta)
      : translation_(translation), theta_(normalized_theta_rad), cos_(cos_theta), sin_(sin_theta) {}

  Eigen::Vector2d translation_ = Eigen::Vector2d::Zero();
  double theta_ = 0.0;
  // cos and sin of theta_, computed once: transforms are applied to millions
  // of points per optimisation round.
  double cos_ = 1.0;
  double sin_ = 0.0;
};

std::ostream& operator<<(std::ostream& os, const Rigid2d& t);

// Returns the largest distance any point within 'radius_m' of 'center' moves
// under 'delta' (a transform applied in the same frame as 'center').
double MaxDisplacementWithin(const Rigid2d& delta, const Eigen::Vector2d& center, double radius_m);

// Returns the rigid transform T (rotation and translation, no scale) that
// minimises sum_i |T * from[i] - to[i]|^2, in closed form (2D Kabsch/Umeyama:
// centroids, then the angle of the summed cross products over the summed dot
// products). Identity for no points; a pure translation for one point or when
// all 'from' points coincide. Throws std::invalid_argument for sizes that differ.
Rigid2d FitRigid2d(const std::vector<Eigen::Vector2d>& from,
                   const std::vector<Eigen::Vector2d>& to);

}  // namespace scout::geometry

#endif  // SCOUT_GEOMETRY_RIGID_TRANSFORM_H_
