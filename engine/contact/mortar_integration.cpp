/// Mortar segmentation (2D segments, 3D auxiliary-plane clipping) and the dual multiplier
/// basis of a slave cell. See mortar_integration.hpp for the contract.
///
/// Choices made here (within the header's contract):
/// - "Facing": slave normal at the slave centre against the master normal at the master
///   centre (reference centroids); a dot product >= 0 gives no overlap.
/// - 2D: the master end nodes are projected on the slave along the slave normal field (the
///   slave point whose normal line passes through the node); the overlap is that interval
///   clipped to [-1, 1]. Each Gauss point is projected on the master along the slave normal
///   at the point, so at an overlap end that is a slave end node the point projection is the
///   projection of that node; the slave end projections are not computed separately.
/// - 3D: polygons of at most 4 vertices are clipped in fixed-size arrays (no allocation).
///   Both polygons are brought to counter-clockwise order in the plane (a facing master is
///   clockwise there); the convex one is the clipper. A vertex closer to a clip line than
///   1e-12 of the slave cell size counts as on the line, so shared edges and vertices
///   (matching meshes, grid lines common to both meshes) produce no spurious intersection
///   points; near-duplicate output vertices are merged with the same tolerance.
/// - Points are projected back along the auxiliary normal: with the cell's nodes projected on
///   the plane once per pair, this is the inverse of the cell's in-plane map, found by Newton
///   from the inverse of its affine part (exact at once on triangles and parallelograms with
///   straight edges: one shape-function evaluation per point). If it fails on either cell (a
///   cell folded with respect to the plane), the pair gives no points (0).
/// - Quadratic faces (TRIA6, QUAD8) are clipped on their vertex polygon. With straight edges
///   in the plane (mid-edge nodes at the middle of their edge, any offset along the normal) the
///   projected cell is that polygon and nothing is lost. With edges curved within the plane,
///   the integrated region is the vertex polygon, not the projection of the curved cell: the
///   covered area is off by (2/3) x (in-plane offset of the mid-edge node) x (edge length)
///   per curved edge, and points near a curved master edge may carry xi_m slightly outside
///   the master reference cell. Neighbouring masters share their vertex-polygon edges, so
///   their overlaps still tile the slave's polygon without gap or double count.
/// - On a curved slave the weights divided by |n_s . n_aux| measure the curved surface above
///   the polygon; the rule is then not exact (the integrand is no longer a polynomial). 2D
///   segments are integrated on the curved SEG3 itself (no polygon), exactly for straight ones.
#include "engine/contact/mortar_integration.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "engine/contact/integration_rules.hpp"
#include "engine/contact/surface_element.hpp"
#include "engine/core/error.hpp"

namespace lunaster::engine::contact::mortar {

namespace {

/// Largest polygon handled by the clipper (two convex quadrangles give at most 8).
constexpr int kMaxPolygon = 16;
/// Highest tabulated orders (integration_rules.hpp): Gauss-Legendre with 6 points (exact to
/// degree 11) on segments, the 12-point triangle rule (exact to degree 6).
constexpr int kMaxSegmentPoints = 6;
constexpr int kMaxTriangleDegree = 6;

double dot3(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void cross3(const double* a, const double* b, double* c) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

double cross2(const double* a, const double* b) { return a[0] * b[1] - a[1] * b[0]; }

/// Euclidean length of (x, y) (std::hypot guards against overflow at a cost not needed here).
double norm2(double x, double y) { return std::sqrt(x * x + y * y); }

/// Gauss-Legendre rule on [-1,1] exact to `degree`: ceil((degree+1)/2) points, at most 6.
/// Rules are built once (thread-safe static initialisation) so calls do not allocate.
const std::vector<ContactQuadPoint>& segment_rule(int degree) {
  static const std::array<std::vector<ContactQuadPoint>, kMaxSegmentPoints + 1> rules = [] {
    std::array<std::vector<ContactQuadPoint>, kMaxSegmentPoints + 1> r;
    for (int n = 1; n <= kMaxSegmentPoints; ++n)
      r[n] = contact_integration_rule(CellType::Seg2, IntegrationScheme::Gauss, n);
    return r;
  }();
  const int n = std::clamp((std::max(degree, 0) + 2) / 2, 1, kMaxSegmentPoints);
  return rules[n];
}

/// Triangle rule (reference area 1/2) exact to `degree`: the tabulated Gauss order n is exact
/// to degree n (1, 3, 4, 6, 7, 12 points for n = 1..6). Above degree 6 the 12-point rule of
/// degree 6 is the highest available and is used (exactness then stops at degree 6).
const std::vector<ContactQuadPoint>& triangle_rule(int degree) {
  static const std::array<std::vector<ContactQuadPoint>, kMaxTriangleDegree + 1> rules = [] {
    std::array<std::vector<ContactQuadPoint>, kMaxTriangleDegree + 1> r;
    for (int n = 1; n <= kMaxTriangleDegree; ++n)
      r[n] = contact_integration_rule(CellType::Tria3, IntegrationScheme::Gauss, n);
    return r;
  }();
  return rules[std::clamp(degree, 1, kMaxTriangleDegree)];
}

void reference_centre(CellType type, double* xi) {
  xi[0] = xi[1] = is_triangle(type) ? 1.0 / 3.0 : 0.0;
  if (surface_ref_dim(type) == 1) xi[0] = xi[1] = 0.0;
}

// ---------------------------------------------------------------------------------------
// 2D: segments.

/// Position x, tangent t = dx/dxi and second derivative h at xi on a segment cell.
void segment_geometry(CellType type, const double* xyz, double xi, double* x, double* t, double* h) {
  double n[3], dn[6], d2n[9];
  const double r[2] = {xi, 0.0};
  surface_shape(type, r, n, dn, d2n);
  for (int i = 0; i < 3; ++i) x[i] = t[i] = h[i] = 0.0;
  for (int a = 0; a < surface_n_nodes(type); ++a)
    for (int i = 0; i < 3; ++i) {
      x[i] += n[a] * xyz[3 * a + i];
      t[i] += dn[2 * a] * xyz[3 * a + i];
      h[i] += d2n[3 * a] * xyz[3 * a + i];
    }
}

/// Round-off level of a Newton step -(x - p) . t / jac on a segment: the difference x - p of
/// two positions carries eps (|x| + |p|), so the step cannot fall below about that times |t| /
/// |jac|. On a short cell far from the origin this exceeds 1e-14 (|jac| ~ |t|^2 ~ h^2 / 4):
/// a test against 1e-14 alone never passes, and Newton reports failure after converging.
double step_noise(const double* x, const double* p, const double* t, double jac) {
  const double scale = std::sqrt(dot3(x, x)) + std::sqrt(dot3(p, p));
  return 16.0 * std::numeric_limits<double>::epsilon() * scale * std::sqrt(dot3(t, t)) / std::abs(jac);
}

/// Slave parameter xi of the point of the slave segment whose normal line passes through p:
/// (x(xi) - p) . t(xi) = 0. Exact for SEG2 (and straight SEG3); Newton from the chord value
/// on a curved SEG3, keeping the chord value if Newton does not converge (such a p lies far
/// outside the cell, where only the side of the interval [-1, 1] it falls on matters).
double slave_foot(CellType type, const double* xyz, const double* p) {
  const double* x0 = xyz;
  const double* x1 = xyz + 3;
  const double d[3] = {x1[0] - x0[0], x1[1] - x0[1], x1[2] - x0[2]};
  const double r[3] = {p[0] - x0[0], p[1] - x0[1], p[2] - x0[2]};
  const double chord = 2.0 * dot3(r, d) / dot3(d, d) - 1.0;
  if (type == CellType::Seg2) return chord;
  double xi = chord;
  for (int it = 0; it < 30; ++it) {
    double x[3], t[3], h[3];
    segment_geometry(type, xyz, xi, x, t, h);
    const double e[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]};
    double jac = dot3(t, t) + dot3(e, h);
    if (!(jac > 1e-14 * dot3(t, t))) jac = dot3(t, t);  // Gauss-Newton where not convex
    if (!(jac > 0.0)) return chord;
    const double step = std::clamp(-dot3(e, t) / jac, -1.0, 1.0);
    xi += step;
    if (!std::isfinite(xi)) return chord;
    if (std::abs(step) <= 1e-14 * std::max(1.0, std::abs(xi)) + step_noise(x, p, t, jac)) return xi;
  }
  return chord;
}

/// Master parameter xi of the point of the master segment on the line through p along the
/// slave normal, i.e. (x(xi) - p) . ts = 0 with ts the slave tangent at p. False when the
/// master is parallel to the normal or Newton (SEG3) does not converge.
bool master_hit_2d(CellType type, const double* xyz, const double* p, const double* ts, double& xi) {
  const double* x0 = xyz;
  const double* x1 = xyz + 3;
  const double d[3] = {x1[0] - x0[0], x1[1] - x0[1], x1[2] - x0[2]};
  const double r[3] = {p[0] - x0[0], p[1] - x0[1], p[2] - x0[2]};
  const double dt = dot3(d, ts);
  if (!(std::abs(dt) > 1e-12 * std::sqrt(dot3(d, d) * dot3(ts, ts)))) return false;
  xi = 2.0 * dot3(r, ts) / dt - 1.0;
  if (type == CellType::Seg2) return std::isfinite(xi);
  for (int it = 0; it < 30; ++it) {
    double x[3], t[3], h[3];
    segment_geometry(type, xyz, xi, x, t, h);
    const double e[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]};
    const double jac = dot3(t, ts);
    if (!(std::abs(jac) > 1e-14 * std::sqrt(dot3(t, t) * dot3(ts, ts)))) return false;
    const double step = std::clamp(-dot3(e, ts) / jac, -1.0, 1.0);
    xi += step;
    if (!std::isfinite(xi)) return false;
    if (std::abs(step) <= 1e-14 * std::max(1.0, std::abs(xi)) + step_noise(x, p, ts, jac)) return true;
  }
  return false;
}

double overlap_2d(CellType st, const double* sx, CellType mt, const double* mx, int degree,
                  std::vector<OverlapPoint>& out) {
  const double centre[2] = {0.0, 0.0};
  const SurfacePoint ps = surface_point(st, sx, centre), pm = surface_point(mt, mx, centre);
  if (!(ps.jacobian > 0.0) || !(pm.jacobian > 0.0) || dot3(ps.n, pm.n) >= 0.0) return 0.0;
  const double p0 = slave_foot(st, sx, mx), p1 = slave_foot(st, sx, mx + 3);
  if (!std::isfinite(p0) || !std::isfinite(p1)) return 0.0;  // slave ends coincide
  const double a = std::max(-1.0, std::min(p0, p1)), b = std::min(1.0, std::max(p0, p1));
  if (!(b - a > 2e-12)) return 0.0;  // empty, or a sliver below 1e-12 of the slave length
  const size_t first = out.size();
  double total = 0.0;
  for (const ContactQuadPoint& q : segment_rule(degree)) {
    OverlapPoint op;
    op.xi_s[0] = 0.5 * (a + b) + 0.5 * (b - a) * q.xi[0];
    double x[3], t[3], h[3];
    segment_geometry(st, sx, op.xi_s[0], x, t, h);
    if (!master_hit_2d(mt, mx, x, t, op.xi_m[0])) {
      out.resize(first);
      return 0.0;
    }
    op.w = q.weight * 0.5 * (b - a) * std::sqrt(dot3(t, t));
    total += op.w;
    out.push_back(op);
  }
  return total;
}

// ---------------------------------------------------------------------------------------
// 3D: auxiliary plane, clipping, back-projection.

struct Polygon {
  int n = 0;
  double p[kMaxPolygon][2];
};

double signed_area(const Polygon& g) {
  double s = 0.0;
  for (int i = 0; i < g.n; ++i) s += cross2(g.p[i], g.p[(i + 1) % g.n]);
  return 0.5 * s;
}

void reverse(Polygon& g) { std::reverse(g.p, g.p + g.n); }

/// Convexity of a counter-clockwise polygon: no turn to the right beyond `tol` (length).
bool convex(const Polygon& g, double tol) {
  for (int i = 0; i < g.n; ++i) {
    const double* a = g.p[i];
    const double* b = g.p[(i + 1) % g.n];
    const double* c = g.p[(i + 2) % g.n];
    const double e[2] = {b[0] - a[0], b[1] - a[1]}, f[2] = {c[0] - b[0], c[1] - b[1]};
    const double len = norm2(e[0], e[1]);
    if (len > 0.0 && cross2(e, f) / len < -tol) return false;
  }
  return true;
}

/// Sutherland-Hodgman: `subject` clipped by the convex counter-clockwise `clipper`. A vertex
/// within `tol` of a clip line is on it (kept, no intersection computed), so an intersection
/// is only computed between vertices strictly on both sides (well-conditioned division).
void clip(const Polygon& subject, const Polygon& clipper, double tol, Polygon& result) {
  Polygon a = subject, b;
  for (int k = 0; k < clipper.n && a.n > 0; ++k) {
    const double* q0 = clipper.p[k];
    const double* q1 = clipper.p[(k + 1) % clipper.n];
    const double e[2] = {q1[0] - q0[0], q1[1] - q0[1]};
    const double len = norm2(e[0], e[1]);
    if (!(len > tol)) continue;  // degenerate clip edge
    double d[kMaxPolygon];
    int side[kMaxPolygon];
    for (int i = 0; i < a.n; ++i) {
      const double r[2] = {a.p[i][0] - q0[0], a.p[i][1] - q0[1]};
      d[i] = cross2(e, r) / len;  // distance, positive on the left (inside)
      side[i] = d[i] > tol ? 1 : d[i] < -tol ? -1 : 0;
    }
    b.n = 0;
    for (int i = 0; i < a.n && b.n < kMaxPolygon; ++i) {
      const int j = (i + a.n - 1) % a.n;  // previous vertex
      if (side[i] * side[j] < 0) {        // strictly on both sides: the crossing point
        const double s = d[j] / (d[j] - d[i]);
        b.p[b.n][0] = a.p[j][0] + s * (a.p[i][0] - a.p[j][0]);
        b.p[b.n][1] = a.p[j][1] + s * (a.p[i][1] - a.p[j][1]);
        ++b.n;
      }
      if (side[i] >= 0 && b.n < kMaxPolygon) {
        b.p[b.n][0] = a.p[i][0], b.p[b.n][1] = a.p[i][1];
        ++b.n;
      }
    }
    a = b;
  }
  // Merge consecutive vertices closer than tol (shared vertices reached from two sides).
  result.n = 0;
  for (int i = 0; i < a.n; ++i) {
    if (result.n > 0) {
      const double* l = result.p[result.n - 1];
      if (norm2(a.p[i][0] - l[0], a.p[i][1] - l[1]) <= tol) continue;
    }
    result.p[result.n][0] = a.p[i][0], result.p[result.n][1] = a.p[i][1];
    ++result.n;
  }
  while (result.n > 1 &&
         norm2(result.p[0][0] - result.p[result.n - 1][0], result.p[0][1] - result.p[result.n - 1][1]) <= tol)
    --result.n;
}

/// A face cell seen in the auxiliary plane: the in-plane coordinates of its nodes, and the
/// affine part of its map (uv = c + L xi: exact for triangles and parallelograms with
/// straight edges) whose inverse starts the Newton iteration of `plane_hit`.
struct PlaneCell {
  CellType type;
  int nn = 0;
  double uv[kMaxSurfaceNodes][2];
  double height = 0.0;  ///< largest distance of a node to the plane
  double c[2] = {0.0, 0.0};
  double inv[2][2] = {{0.0, 0.0}, {0.0, 0.0}};  ///< L^-1
  bool valid = false;                           ///< L invertible
};

PlaneCell plane_cell(CellType type, const double* xyz, const double* x0, const double* n0, const double (*e)[3]) {
  PlaneCell g;
  g.type = type, g.nn = surface_n_nodes(type);
  for (int a = 0; a < g.nn; ++a) {
    const double r[3] = {xyz[3 * a] - x0[0], xyz[3 * a + 1] - x0[1], xyz[3 * a + 2] - x0[2]};
    g.uv[a][0] = dot3(r, e[0]), g.uv[a][1] = dot3(r, e[1]);
    g.height = std::max(g.height, std::abs(dot3(r, n0)));
  }
  double l0[2], l1[2];  // columns of L
  if (is_triangle(type)) {
    g.c[0] = g.uv[0][0], g.c[1] = g.uv[0][1];
    for (int i = 0; i < 2; ++i) l0[i] = g.uv[1][i] - g.uv[0][i], l1[i] = g.uv[2][i] - g.uv[0][i];
  } else {
    for (int i = 0; i < 2; ++i) {
      g.c[i] = 0.25 * (g.uv[0][i] + g.uv[1][i] + g.uv[2][i] + g.uv[3][i]);
      l0[i] = 0.25 * (-g.uv[0][i] + g.uv[1][i] + g.uv[2][i] - g.uv[3][i]);
      l1[i] = 0.25 * (-g.uv[0][i] - g.uv[1][i] + g.uv[2][i] + g.uv[3][i]);
    }
  }
  const double det = l0[0] * l1[1] - l1[0] * l0[1];
  g.valid = std::abs(det) > 1e-14 * norm2(l0[0], l0[1]) * norm2(l1[0], l1[1]);
  if (g.valid) {
    g.inv[0][0] = l1[1] / det, g.inv[0][1] = -l1[0] / det;
    g.inv[1][0] = -l0[1] / det, g.inv[1][1] = l0[0] / det;
  }
  return g;
}

/// The reference point of the cell whose projection on the plane is q (in-plane
/// coordinates), i.e. the cell's point on the line through q along the auxiliary normal.
/// Newton on sum_a N_a(xi) uv_a = q from the affine inverse (one evaluation on affine
/// cells: the first step is at rounding level); steps are limited to one reference unit.
/// False if the cell is edge-on to the plane there or the iteration does not converge.
bool plane_hit(const PlaneCell& g, const double* q, double* xi) {
  if (!g.valid) return false;
  const double d[2] = {q[0] - g.c[0], q[1] - g.c[1]};
  xi[0] = g.inv[0][0] * d[0] + g.inv[0][1] * d[1];
  xi[1] = g.inv[1][0] * d[0] + g.inv[1][1] * d[1];
  double n[kMaxSurfaceNodes], dn[2 * kMaxSurfaceNodes];
  for (int it = 0; it < 40; ++it) {
    surface_shape(g.type, xi, n, dn, nullptr);
    double r[2] = {-q[0], -q[1]}, j[2][2] = {{0.0, 0.0}, {0.0, 0.0}};  // j[i][k] = du_i / dxi_k
    for (int a = 0; a < g.nn; ++a)
      for (int i = 0; i < 2; ++i) {
        r[i] += n[a] * g.uv[a][i];
        j[i][0] += dn[2 * a] * g.uv[a][i], j[i][1] += dn[2 * a + 1] * g.uv[a][i];
      }
    const double det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    if (!(std::abs(det) > 1e-14 * norm2(j[0][0], j[1][0]) * norm2(j[0][1], j[1][1]))) return false;
    double s0 = -(j[1][1] * r[0] - j[0][1] * r[1]) / det, s1 = -(j[0][0] * r[1] - j[1][0] * r[0]) / det;
    const double len = norm2(s0, s1);
    if (len > 1.0) s0 /= len, s1 /= len;
    xi[0] += s0, xi[1] += s1;
    if (!std::isfinite(xi[0]) || !std::isfinite(xi[1])) return false;
    // Quadratic convergence: after a step below 1e-9 the error left is of order 1e-18 times
    // the map's second derivatives over its first (rounding level on any sensible cell).
    if (len <= 1e-9) return true;
  }
  return false;
}

double overlap_3d(CellType st, const double* sx, CellType mt, const double* mx, int degree,
                  std::vector<OverlapPoint>& out) {
  double cs[2], cm[2];
  reference_centre(st, cs), reference_centre(mt, cm);
  const SurfacePoint ps = surface_point(st, sx, cs), pm = surface_point(mt, mx, cm);
  if (!(ps.jacobian > 0.0) || !(pm.jacobian > 0.0) || dot3(ps.n, pm.n) >= 0.0) return 0.0;
  // Auxiliary plane: origin x0, normal n0, axes e[0], e[1] with e[0] x e[1] = n0.
  const double* x0 = ps.x;
  const double* n0 = ps.n;
  double e[2][3];
  const double tl = std::sqrt(dot3(ps.t[0], ps.t[0]));
  for (int i = 0; i < 3; ++i) e[0][i] = ps.t[0][i] / tl;  // t0 is orthogonal to n0
  cross3(n0, e[0], e[1]);
  const PlaneCell gs = plane_cell(st, sx, x0, n0, e), gm = plane_cell(mt, mx, x0, n0, e);
  Polygon slave, master;
  slave.n = surface_n_vertices(st), master.n = surface_n_vertices(mt);
  std::copy(&gs.uv[0][0], &gs.uv[0][0] + 2 * slave.n, &slave.p[0][0]);
  std::copy(&gm.uv[0][0], &gm.uv[0][0] + 2 * master.n, &master.p[0][0]);
  double area_s = signed_area(slave), area_m = signed_area(master);
  if (area_s < 0.0) reverse(slave), area_s = -area_s;
  if (area_m < 0.0) reverse(master), area_m = -area_m;  // the facing master is clockwise
  if (!(area_s > 0.0) || !(area_m > 1e-12 * area_s)) return 0.0;
  const double size = std::sqrt(area_s), tol = 1e-12 * size;
  Polygon poly;
  if (convex(master, tol) || !convex(slave, tol))
    clip(slave, master, tol, poly);
  else
    clip(master, slave, tol, poly);
  if (poly.n < 3) return 0.0;
  const double area = signed_area(poly);
  if (!(area > 1e-12 * area_s)) return 0.0;  // sliver
  double c[2] = {0.0, 0.0};
  for (int i = 0; i < poly.n; ++i) c[0] += poly.p[i][0] / poly.n, c[1] += poly.p[i][1] / poly.n;
  const std::vector<ContactQuadPoint>& rule = triangle_rule(degree);
  // On a flat slave (nodes within 1e-12 of its size from the plane) n_s . n0 = 1 to
  // rounding: no need to evaluate it per point.
  const bool flat_slave = gs.height <= 1e-12 * size;
  const size_t first = out.size();
  double total = 0.0;
  for (int k = 0; k < poly.n; ++k) {
    const double* p1 = poly.p[k];
    const double* p2 = poly.p[(k + 1) % poly.n];
    const double a[2] = {p1[0] - c[0], p1[1] - c[1]}, b[2] = {p2[0] - c[0], p2[1] - c[1]};
    const double tri = 0.5 * cross2(a, b);
    if (!(tri > 1e-14 * area)) continue;  // collinear vertices: no area to integrate
    for (const ContactQuadPoint& r : rule) {
      const double q[2] = {c[0] + r.xi[0] * a[0] + r.xi[1] * b[0], c[1] + r.xi[0] * a[1] + r.xi[1] * b[1]};
      OverlapPoint op;
      bool ok = plane_hit(gs, q, op.xi_s) && plane_hit(gm, q, op.xi_m);
      double cosine = 1.0;
      if (ok && !flat_slave) cosine = std::abs(dot3(surface_point(st, sx, op.xi_s).n, n0));
      if (!ok || !(cosine > 1e-8)) {
        out.resize(first);
        return 0.0;
      }
      op.w = r.weight * 2.0 * tri / cosine;
      total += op.w;
      out.push_back(op);
    }
  }
  return total;
}

}  // namespace

double overlap_points(CellType st, const double* sx, CellType mt, const double* mx, int degree,
                      std::vector<OverlapPoint>& out) {
  LUNASTER_ASSERT(is_surface_type(st) && is_surface_type(mt), "mortar overlap of a non-surface cell");
  LUNASTER_ASSERT(surface_ref_dim(st) == surface_ref_dim(mt), "mortar overlap of a segment with a face");
  if (surface_ref_dim(st) == 1) return overlap_2d(st, sx, mt, mx, degree, out);
  return overlap_3d(st, sx, mt, mx, degree, out);
}

bool transformed_slave(CellType type) { return type == CellType::Tria6 || type == CellType::Quad8; }

void slave_shape(CellType type, const double* xi, double* n) {
  surface_shape(type, xi, n, nullptr, nullptr);
  if (!transformed_slave(type)) return;
  const int nv = surface_n_vertices(type), nn = surface_n_nodes(type);
  for (int m = nv; m < nn; ++m) {  // mid-edge node m sits on the edge (m - nv, m - nv + 1)
    const int v1 = m - nv, v2 = (m - nv + 1) % nv;
    n[v1] += kQuadraticAlpha * n[m];
    n[v2] += kQuadraticAlpha * n[m];
    n[m] *= 1.0 - 2.0 * kQuadraticAlpha;
  }
}

bool edge_vertices(CellType type, int local_node, int* v1, int* v2) {
  const int nv = surface_n_vertices(type), nn = surface_n_nodes(type);
  if (local_node < nv || local_node >= nn) return false;
  // MED order: mid-edge node nv + e on the edge from vertex e to vertex e + 1 (cyclic);
  // SEG3's middle node joins the two ends.
  *v1 = local_node - nv;
  *v2 = (local_node - nv + 1) % nv;
  return true;
}

bool dual_coefficients(CellType type, const std::vector<OverlapPoint>& points, double* a) {
  // On a partially covered cell Me is ill-conditioned (reciprocal condition 3e-4 and
  // coefficients of several hundred for a TRIA6 covered on 16 %): solved in double only, the
  // sums of the coefficients over i (1: the dual functions sum to one) drift by 1e-11. So Me
  // and De are accumulated in extended precision (long double: 64-bit mantissa on x86-64),
  // factorised in double, and one refinement step uses the residual De - Me A^T computed in
  // extended precision (mixed-precision refinement): the sums then hold to 1e-13.
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxSurfaceNodes,
                               kMaxSurfaceNodes>;
  const int nn = surface_n_nodes(type);
  long double me[kMaxSurfaceNodes][kMaxSurfaceNodes] = {}, de[kMaxSurfaceNodes] = {};
  double n[kMaxSurfaceNodes];
  for (const OverlapPoint& p : points) {
    slave_shape(type, p.xi_s, n);
    for (int i = 0; i < nn; ++i) {
      const long double wi = static_cast<long double>(p.w) * n[i];
      de[i] += wi;
      for (int j = i; j < nn; ++j) me[i][j] += wi * n[j];
    }
  }
  Matrix m(nn, nn), d = Matrix::Zero(nn, nn);
  // A node whose shape function integrates to zero over the cell carries no multiplier: its
  // Phi_i is zero and the others stay biorthogonal to it. This is the vertex on the axis of
  // an AXIS SEG3 (the integral of N_v r dl vanishes exactly there); a clearly negative
  // integral (a QUAD8/SEG3 corner on a small covered part) still means no dual basis.
  long double total = 0.0L;
  for (int i = 0; i < nn; ++i) total += de[i] < 0 ? -de[i] : de[i];
  for (int i = 0; i < nn; ++i)
    if ((de[i] < 0 ? -de[i] : de[i]) <= 1e-12L * total) de[i] = 0.0L;
  for (int i = 0; i < nn; ++i) {
    if (!(de[i] >= 0)) return false;
    d(i, i) = static_cast<double>(de[i]);
    for (int j = 0; j < i; ++j) me[i][j] = me[j][i];
    for (int j = 0; j < nn; ++j) m(i, j) = static_cast<double>(me[i][j]);
  }
  const Eigen::FullPivLU<Matrix> lu(m);
  // Rank (pivots against the largest one) and the reciprocal condition estimate in the
  // 1-norm: the estimate alone is not reliable on an exactly rank-deficient matrix.
  if (!lu.isInvertible() || !(lu.rcond() >= 1e-12)) return false;
  Matrix at = lu.solve(d);  // Me is symmetric: A^T = Me^-1 De
  Matrix residual(nn, nn);
  for (int i = 0; i < nn; ++i)
    for (int k = 0; k < nn; ++k) {
      long double r = i == k ? de[i] : 0.0L;
      for (int j = 0; j < nn; ++j) r -= me[i][j] * at(j, k);
      residual(i, k) = static_cast<double>(r);
    }
  at += lu.solve(residual);
  for (int i = 0; i < nn; ++i)
    for (int j = 0; j < nn; ++j)
      if (!std::isfinite(at(j, i))) return false;
  for (int i = 0; i < nn; ++i)
    for (int j = 0; j < nn; ++j) a[i * nn + j] = at(j, i);
  return true;
}

}  // namespace lunaster::engine::contact::mortar
