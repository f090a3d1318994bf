#include "tools/render/primitives.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace houghloc {
namespace {

constexpr double kEps = 1e-9;

bool sphereHit(const Eigen::Vector3d& center, double r, const Eigen::Vector3d& o,
               const Eigen::Vector3d& d, Hit& hit) {
  const Eigen::Vector3d oc = o - center;
  const double b = oc.dot(d);
  const double c = oc.squaredNorm() - r * r;
  const double h = b * b - c;
  if (h < 0.0) return false;
  double t = -b - std::sqrt(h);
  if (t <= kEps) t = -b + std::sqrt(h);
  if (t <= kEps || t >= hit.t) return false;
  hit.t = t;
  hit.normal = (o + t * d - center) / r;
  return true;
}

/// Capsule intersection after Inigo Quilez (iquilezles.org, "intersectors").
bool capsuleHit(const Eigen::Vector3d& pa, const Eigen::Vector3d& pb, double r,
                const Eigen::Vector3d& o, const Eigen::Vector3d& d, Hit& hit) {
  const Eigen::Vector3d ba = pb - pa, oa = o - pa;
  const double baba = ba.dot(ba), bard = ba.dot(d), baoa = ba.dot(oa);
  const double rdoa = d.dot(oa), oaoa = oa.dot(oa);
  const double a = baba - bard * bard;
  double b = baba * rdoa - baoa * bard;
  double c = baba * oaoa - baoa * baoa - r * r * baba;
  double h = b * b - a * c;
  if (h < 0.0) return false;
  double t = -1.0;
  if (a > kEps) {
    t = (-b - std::sqrt(h)) / a;
    const double y = baoa + t * bard;
    if (!(y > 0.0 && y < baba)) t = -1.0;
  }
  if (t <= kEps) {
    // The caps: the nearer sphere end.
    const double y = baoa + ((a > kEps) ? (-b - std::sqrt(h)) / a : 0.0) * bard;
    const Eigen::Vector3d oc = (y <= 0.0) ? oa : Eigen::Vector3d(o - pb);
    b = d.dot(oc);
    c = oc.dot(oc) - r * r;
    h = b * b - c;
    if (h <= 0.0) return false;
    t = -b - std::sqrt(h);
  }
  if (t <= kEps || t >= hit.t) return false;
  const Eigen::Vector3d p = o + t * d - pa;
  const double k = std::clamp(p.dot(ba) / std::max(kEps, baba), 0.0, 1.0);
  hit.t = t;
  hit.normal = (p - k * ba) / r;
  return true;
}

bool boxHit(const Primitive& box, const Eigen::Vector3d& o, const Eigen::Vector3d& d, Hit& hit) {
  const double c = std::cos(box.yaw), s = std::sin(box.yaw);
  const Eigen::Vector3d q = o - box.a;
  // Into the box frame (rotate by -yaw).
  const Eigen::Vector3d lo(c * q.x() + s * q.y(), -s * q.x() + c * q.y(), q.z());
  const Eigen::Vector3d ld(c * d.x() + s * d.y(), -s * d.x() + c * d.y(), d.z());
  double t_near = -1e30, t_far = 1e30;
  int axis = 0;
  double sign = 1.0;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(ld[i]) < kEps) {
      if (std::abs(lo[i]) > box.b[i]) return false;
      continue;
    }
    double t1 = (-box.b[i] - lo[i]) / ld[i], t2 = (box.b[i] - lo[i]) / ld[i];
    const double s1 = ld[i] > 0.0 ? -1.0 : 1.0;
    if (t1 > t2) std::swap(t1, t2);
    if (t1 > t_near) {
      t_near = t1;
      axis = i;
      sign = s1;
    }
    t_far = std::min(t_far, t2);
  }
  if (t_near > t_far || t_near <= kEps || t_near >= hit.t) return false;
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  n[axis] = sign;
  hit.t = t_near;
  hit.normal = Eigen::Vector3d(c * n.x() - s * n.y(), s * n.x() + c * n.y(), n.z());
  return true;
}

bool panelHit(const Primitive& p, const Eigen::Vector3d& o, const Eigen::Vector3d& d, Hit& hit) {
  const Eigen::Vector3d n = p.b.cross(p.c);
  const double denom = n.dot(d);
  if (std::abs(denom) < kEps) return false;
  const double t = n.dot(p.a - o) / denom;
  if (t <= kEps || t >= hit.t) return false;
  const Eigen::Vector3d q = o + t * d - p.a;
  // Coordinates along the two edges (they need not be orthogonal).
  const double bb = p.b.dot(p.b), bc = p.b.dot(p.c), cc = p.c.dot(p.c);
  const double qb = q.dot(p.b), qc = q.dot(p.c);
  const double det = bb * cc - bc * bc;
  const double u = (qb * cc - qc * bc) / det, v = (qc * bb - qb * bc) / det;
  if (u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0) return false;
  hit.t = t;
  hit.normal = n.normalized();
  hit.uv = Eigen::Vector2d(u * std::sqrt(bb), v * std::sqrt(cc));
  return true;
}

}  // namespace

Eigen::Vector3d Primitive::boundCenter() const {
  switch (kind) {
    case Kind::kCapsule:
      return 0.5 * (a + b);
    case Kind::kPanel:
      return a + 0.5 * (b + c);
    default:
      return a;
  }
}

double Primitive::boundRadius() const {
  switch (kind) {
    case Kind::kSphere:
      return radius;
    case Kind::kCapsule:
      return 0.5 * (b - a).norm() + radius;
    case Kind::kBox:
      return b.norm();
    case Kind::kPanel:
      return 0.5 * std::max((b + c).norm(), (b - c).norm());
  }
  return 0.0;
}

bool Primitive::intersect(const Eigen::Vector3d& o, const Eigen::Vector3d& d, Hit& hit) const {
  switch (kind) {
    case Kind::kSphere:
      return sphereHit(a, radius, o, d, hit);
    case Kind::kCapsule:
      return capsuleHit(a, b, radius, o, d, hit);
    case Kind::kBox:
      return boxHit(*this, o, d, hit);
    case Kind::kPanel:
      return panelHit(*this, o, d, hit);
  }
  return false;
}

Primitive makeSphere(const Eigen::Vector3d& center, double radius, const Material& m) {
  Primitive p;
  p.kind = Primitive::Kind::kSphere;
  p.a = center;
  p.radius = radius;
  p.material = m;
  return p;
}

Primitive makeCapsule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius,
                      const Material& m) {
  Primitive p;
  p.kind = Primitive::Kind::kCapsule;
  p.a = a;
  p.b = b;
  p.radius = radius;
  p.material = m;
  return p;
}

Primitive makeBox(const Eigen::Vector3d& center, const Eigen::Vector3d& half_extents, double yaw,
                  const Material& m) {
  Primitive p;
  p.kind = Primitive::Kind::kBox;
  p.a = center;
  p.b = half_extents;
  p.yaw = yaw;
  p.material = m;
  return p;
}

Primitive makeNetPanel(const Eigen::Vector3d& corner, const Eigen::Vector3d& edge1,
                       const Eigen::Vector3d& edge2, const Material& m) {
  Primitive p;
  p.kind = Primitive::Kind::kPanel;
  p.a = corner;
  p.b = edge1;
  p.c = edge2;
  p.material = m;
  p.material.pattern = Pattern::kNet;
  p.opaque = false;
  return p;
}

}  // namespace houghloc
