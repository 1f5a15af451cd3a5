#include "physics/clump_mass.hpp"

#include "physics/principal_axes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace mpdem {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTouch = 1e-12;       // relative: |xi - xj| >= (ri + rj)(1 - kTouch) is touching, not overlapping
constexpr double kTarget = 1e-8;       // relative error at which the doubling of the rules stops
constexpr double kErrorFloor = 1e-13;  // relative: round-off of the sums, the least error an integration reports
constexpr int kLevels = 5;             // rules of 6, 12, 24, 48, 96 points per segment

// Raw moments about one origin: volume (m^3), first moment (m^4), second moment sum p p^T (m^5).
struct Moments {
  double v = 0.0;
  Vec3 m1;
  Mat3 s{};
  Moments& operator+=(const Moments& o) {
    v += o.v;
    m1 += o.m1;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s[i][j] += o.s[i][j];
    return *this;
  }
};

// The same moments about an origin moved by -d (p -> p + d).
Moments shifted(Moments m, const Vec3& d) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m.s[i][j] += m.m1[i] * d[j] + d[i] * m.m1[j] + m.v * d[i] * d[j];
  m.m1 += m.v * d;
  return m;
}

struct Sphere {
  Vec3 c;  // m, centre relative to the cluster's origin
  double r;
};

// Gauss-Legendre rule of n points carried to t in [0, pi] with u = (a + b)/2 - (b - a)/2 cos t:
// on a segment [a, b] the nodes are (a + b)/2 - (b - a)/2 c[k], the weights (b - a)/2 w[k].
struct SegmentRule {
  std::vector<double> c, w;  // -, cos t_k and (pi/2) w_k sin t_k; shape [n]
};

SegmentRule make_rule(int n) {
  SegmentRule rule;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {  // Newton on P_n, from the classic first guess
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) std::tie(p0, p1) = std::pair{p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k};
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    const double weight = 2.0 / ((1.0 - x * x) * dp * dp), t = 0.5 * kPi * (1.0 + x);
    rule.c.push_back(std::cos(t));
    rule.w.push_back(0.5 * kPi * weight * std::sin(t));
  }
  return rule;
}

const SegmentRule& segment_rule(int level) {
  static const std::array<SegmentRule, kLevels> rules = {make_rule(6), make_rule(12), make_rule(24), make_rule(48),
                                                         make_rule(96)};
  return rules[level];
}

// Intersections of the circles (u1, v1, r1) and (u2, v2, r2) of one plane, as (u, v).
void circle_crossings(double u1, double v1, double r1, double u2, double v2, double r2,
                      std::vector<std::array<double, 2>>& out) {
  const double du = u2 - u1, dv = v2 - v1, d2 = du * du + dv * dv, d = std::sqrt(d2);
  if (!(d > std::abs(r1 - r2)) || !(d < r1 + r2)) return;
  const double a = (d2 + r1 * r1 - r2 * r2) / (2.0 * d), h = std::sqrt(std::max(0.0, r1 * r1 - a * a));
  out.push_back({u1 + (a * du - h * dv) / d, v1 + (a * dv + h * du) / d});
  out.push_back({u1 + (a * du + h * dv) / d, v1 + (a * dv - h * du) / d});
}

// Whether p lies strictly inside one of the spheres:
// a breakpoint there is no breakpoint of the union's integrand, whatever the members inside do.
constexpr double kInside = 1e-9;  // relative margin: on a member's surface is not inside
bool inside_any(const Vec3& p, const std::vector<Sphere>& s) {
  for (const Sphere& sp : s)
    if (norm2(p - sp.c) < sp.r * sp.r * (1.0 - kInside)) return true;
  return false;
}

// The x where the integrand across a plane x = const stops being smooth (header comment), less
// those inside another member.
std::vector<double> x_breakpoints(const std::vector<Sphere>& s) {
  std::vector<double> xb;
  std::vector<std::array<double, 2>> uv;
  const std::size_t n = s.size();
  auto add = [&](const Vec3& p) {
    if (!inside_any(p, s)) xb.push_back(p.x);
  };
  auto meet = [&](std::size_t i, std::size_t j) {
    const double d = norm(s[j].c - s[i].c);
    return d < s[i].r + s[j].r && d > std::abs(s[i].r - s[j].r);
  };
  for (std::size_t i = 0; i < n; ++i) {
    add(s[i].c - Vec3{s[i].r, 0.0, 0.0});
    add(s[i].c + Vec3{s[i].r, 0.0, 0.0});
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      const double dz = s[j].c.z - s[i].c.z;  // sphere j in the plane of sphere i's z-equator
      uv.clear();
      if (std::abs(dz) < s[j].r)
        circle_crossings(s[i].c.x, s[i].c.y, s[i].r, s[j].c.x, s[j].c.y, std::sqrt(s[j].r * s[j].r - dz * dz), uv);
      for (const auto& [u, v] : uv) add({u, v, s[i].c.z});
      if (j < i || !meet(i, j)) continue;
      // The intersection circle (centre cc, radius a, plane normal e/d): its points of extreme x.
      const Vec3 e = s[j].c - s[i].c;
      const double d = norm(e), t = (d * d + s[i].r * s[i].r - s[j].r * s[j].r) / (2.0 * d);
      const double a = std::sqrt(std::max(0.0, s[i].r * s[i].r - t * t));
      const Vec3 cc = s[i].c + (t / d) * e, xp = Vec3{1.0, 0.0, 0.0} - (e.x / (d * d)) * e;
      const double lxp = norm(xp);
      if (lxp > 1e-12) {
        add(cc - (a / lxp) * xp);
        add(cc + (a / lxp) * xp);
      } else {
        xb.push_back(cc.x);  // the circle lies in a plane x = const
      }
      for (std::size_t k = j + 1; k < n; ++k) {
        if (!meet(i, k) || !meet(j, k)) continue;
        // Points on all three: q = p - c_i = alpha e + beta f on the radical line, plus +-h along e x f.
        const Vec3 f = s[k].c - s[i].c, u = cross(e, f);
        const double ee = dot(e, e), ef = dot(e, f), ff = dot(f, f), det = ee * ff - ef * ef;
        if (!(dot(u, u) > 1e-24 * ee * ff)) continue;  // collinear centres: the circles' extents cover it
        const double b1 = 0.5 * (ee + s[i].r * s[i].r - s[j].r * s[j].r);
        const double b2 = 0.5 * (ff + s[i].r * s[i].r - s[k].r * s[k].r);
        const double alpha = (b1 * ff - b2 * ef) / det, beta = (b2 * ee - b1 * ef) / det;
        const Vec3 q = alpha * e + beta * f;
        const double h2 = (s[i].r * s[i].r - norm2(q)) / norm2(u);
        if (h2 <= 0.0) continue;
        add(s[i].c + q - std::sqrt(h2) * u);
        add(s[i].c + q + std::sqrt(h2) * u);
      }
    }
  }
  std::sort(xb.begin(), xb.end());
  return xb;
}

// Union moments of overlapping spheres (coordinates about their own origin) with `rule` on every
// segment between the breakpoints `xb` (sorted).
Moments integrate_cluster(const std::vector<Sphere>& s, const std::vector<double>& xb, const SegmentRule& rule) {
  struct Disk {
    double y, z, r;  // m, cross-section of a sphere in a plane x = const
  };
  std::vector<Disk> disks, active;
  std::vector<double> yb;                     // m, breakpoints in y of one plane x = const
  std::vector<std::array<double, 2>> uv;      // m, candidate breakpoints (y, z)
  std::vector<std::pair<double, double>> iv;  // m, z intervals along one line
  const double scale = xb.back() - xb.front();
  Moments m;
  for (std::size_t a = 0; a + 1 < xb.size(); ++a) {
    const double xa = xb[a], xe = xb[a + 1];
    if (!(xe - xa > 1e-15 * scale)) continue;
    const double xm = 0.5 * (xa + xe), xh = 0.5 * (xe - xa);
    for (std::size_t kx = 0; kx < rule.c.size(); ++kx) {
      const double x = xm - xh * rule.c[kx], wx = xh * rule.w[kx];
      disks.clear();
      uv.clear();
      for (const Sphere& sp : s) {
        const double r2 = sp.r * sp.r - (x - sp.c.x) * (x - sp.c.x);
        if (r2 <= 0.0) continue;
        disks.push_back({sp.c.y, sp.c.z, std::sqrt(r2)});
        uv.push_back({sp.c.y - disks.back().r, sp.c.z});
        uv.push_back({sp.c.y + disks.back().r, sp.c.z});
      }
      for (std::size_t i = 0; i < disks.size(); ++i)
        for (std::size_t j = i + 1; j < disks.size(); ++j)
          circle_crossings(disks[i].y, disks[i].z, disks[i].r, disks[j].y, disks[j].z, disks[j].r, uv);
      yb.clear();
      for (const auto& [y, z] : uv) {
        bool inside = false;  // as inside_any, in the plane
        for (const Disk& d : disks)
          inside = inside || (y - d.y) * (y - d.y) + (z - d.z) * (z - d.z) < d.r * d.r * (1.0 - kInside);
        if (!inside) yb.push_back(y);
      }
      if (yb.empty()) continue;
      std::sort(yb.begin(), yb.end());
      double g0 = 0.0, gy = 0.0, gyy = 0.0, gz = 0.0, gyz = 0.0, gzz = 0.0;  // integrals over y of the line's
      for (std::size_t b = 0; b + 1 < yb.size(); ++b) {
        if (!(yb[b + 1] - yb[b] > 1e-15 * scale)) continue;
        const double ym = 0.5 * (yb[b] + yb[b + 1]), yh = 0.5 * (yb[b + 1] - yb[b]);
        active.clear();
        for (const Disk& d : disks)  // an extent inside another disk is no breakpoint: test the whole segment
          if (d.y - d.r < yb[b + 1] && d.y + d.r > yb[b]) active.push_back(d);
        if (active.empty()) continue;
        for (std::size_t ky = 0; ky < rule.c.size(); ++ky) {
          const double y = ym - yh * rule.c[ky], wy = yh * rule.w[ky];
          iv.clear();
          for (const Disk& d : active) {
            const double h = std::sqrt(std::max(0.0, d.r * d.r - (y - d.y) * (y - d.y)));
            iv.emplace_back(d.z - h, d.z + h);
          }
          std::sort(iv.begin(), iv.end());
          double len = 0.0, z1 = 0.0, z2 = 0.0;  // integrals of 1, z, z^2 over the merged intervals
          double za = iv[0].first, zb = iv[0].second;
          for (std::size_t k = 1; k <= iv.size(); ++k) {
            if (k < iv.size() && iv[k].first <= zb) {
              zb = std::max(zb, iv[k].second);
              continue;
            }
            len += zb - za;
            z1 += 0.5 * (zb - za) * (zb + za);
            z2 += (zb - za) * (zb * zb + zb * za + za * za) / 3.0;
            if (k < iv.size()) std::tie(za, zb) = iv[k];
          }
          g0 += wy * len;
          gy += wy * y * len;
          gyy += wy * y * y * len;
          gz += wy * z1;
          gyz += wy * y * z1;
          gzz += wy * z2;
        }
      }
      m.v += wx * g0;
      m.m1 += Vec3{wx * x * g0, wx * gy, wx * gz};
      const double sxx = wx * x * x * g0, sxy = wx * x * gy, sxz = wx * x * gz;
      const double syy = wx * gyy, syz = wx * gyz, szz = wx * gzz;
      m.s[0][0] += sxx, m.s[0][1] += sxy, m.s[0][2] += sxz, m.s[1][1] += syy, m.s[1][2] += syz, m.s[2][2] += szz;
    }
  }
  m.s[1][0] = m.s[0][1], m.s[2][0] = m.s[0][2], m.s[2][1] = m.s[1][2];
  return m;
}

Mat3 inertia_about_centroid(const Moments& m, Vec3& centroid) {
  centroid = m.m1 / m.v;
  Mat3 sc{}, inertia{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) sc[i][j] = m.s[i][j] - m.v * centroid[i] * centroid[j];
  const double trace = sc[0][0] + sc[1][1] + sc[2][2];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) inertia[i][j] = (i == j ? trace : 0.0) - sc[i][j];
  return inertia;
}

void check_members(const std::vector<ClumpMember>& members) {
  if (members.empty()) throw std::invalid_argument("a clump template needs at least one member sphere");
  for (std::size_t i = 0; i < members.size(); ++i) {
    const ClumpMember& m = members[i];
    std::ostringstream which;
    which << "member " << i + 1 << ": ";
    if (!isfinite(m.x) || !std::isfinite(m.r)) throw std::invalid_argument(which.str() + "a value is not finite");
    which << "radius must be > 0 (got " << m.r << ")";
    if (!(m.r > 0.0)) throw std::invalid_argument(which.str());
  }
}

}  // namespace

ClumpMassProperties clump_mass_properties(const std::vector<ClumpMember>& members) {
  check_members(members);
  const std::size_t n = members.size();
  Vec3 origin;  // m, mean of the centres: the sums are taken about it
  for (const ClumpMember& m : members) origin += m.x / static_cast<double>(n);

  // Clusters of overlapping members (connected components), by repeated labelling.
  std::vector<std::size_t> label(n);
  for (std::size_t i = 0; i < n; ++i) label[i] = i;
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        const double touch = (members[i].r + members[j].r) * (1.0 - kTouch);
        if (label[i] == label[j] || !(norm2(members[j].x - members[i].x) < touch * touch)) continue;
        label[i] = label[j] = std::min(label[i], label[j]);
        changed = true;
      }
  }

  ClumpMassProperties out;
  Moments exact;
  struct Cluster {
    std::vector<Sphere> spheres;
    Vec3 centre;  // m, the cluster's origin relative to `origin`
    std::vector<double> xb;
  };
  std::vector<Cluster> clusters;
  for (std::size_t i = 0; i < n; ++i) {
    const bool alone = std::count(label.begin(), label.end(), label[i]) == 1;
    const Vec3 c = members[i].x - origin;
    const double r = members[i].r;
    if (alone) {
      Moments m;
      m.v = 4.0 / 3.0 * kPi * r * r * r;
      m.m1 = m.v * c;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) m.s[a][b] = m.v * c[a] * c[b] + (a == b ? 0.2 * m.v * r * r : 0.0);
      exact += m;
      continue;
    }
    if (label[i] != i) continue;  // the cluster's first member gathers it
    Cluster cl;
    std::size_t count = 0;
    for (std::size_t j = i; j < n; ++j)
      if (label[j] == i) cl.centre += members[j].x - origin, ++count;
    cl.centre /= static_cast<double>(count);
    for (std::size_t j = i; j < n; ++j)
      if (label[j] == i) cl.spheres.push_back({members[j].x - origin - cl.centre, members[j].r});
    cl.xb = x_breakpoints(cl.spheres);
    clusters.push_back(std::move(cl));
  }
  out.overlapping = !clusters.empty();

  auto total = [&](int level) {
    Moments m = exact;
    for (const Cluster& cl : clusters)
      m += shifted(integrate_cluster(cl.spheres, cl.xb, segment_rule(level)), cl.centre);
    return m;
  };
  Moments m = total(0);
  Vec3 centroid;
  Mat3 inertia = inertia_about_centroid(m, centroid);
  if (out.overlapping) {
    for (int level = 1; level < kLevels; ++level) {
      const Moments fine = total(level);
      const Mat3 fine_inertia = inertia_about_centroid(fine, centroid);
      double change2 = 0.0;  // m^10, squared Frobenius norm of the inertia tensor's change
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) change2 += std::pow(fine_inertia[i][j] - inertia[i][j], 2);
      out.volume_error = std::max(kErrorFloor, std::abs(fine.v - m.v) / fine.v);
      out.inertia_error = std::max(kErrorFloor, std::sqrt(change2) / principal_axes(fine_inertia).moments.x);
      m = fine;
      inertia = fine_inertia;
      if (out.volume_error < kTarget && out.inertia_error < kTarget) break;
    }
  }
  // Moments equal within the error estimate count as equal (their axes keep the input order).
  const PrincipalAxes pa = principal_axes(inertia, std::max(kTieDefault, out.inertia_error));

  out.volume = m.v;
  out.centroid = centroid + origin;
  out.inertia = inertia;
  out.principal = pa.moments;
  out.to_input = quat_from_matrix(pa.axes);
  Mat3 to_principal{};  // the transpose of pa.axes
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) to_principal[i][j] = pa.axes[j][i];
  for (const ClumpMember& mem : members)
    out.members_principal.push_back({mat_apply(to_principal, mem.x - out.centroid), mem.r});
  return out;
}

}  // namespace mpdem
