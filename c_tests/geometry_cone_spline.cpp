/*
 * Independent geometry checks of cone spline surfaces (issue 8), from the exported NURBS
 * and Bézier views only, with the suite's own evaluator, OpenMesh and VTK:
 *
 *  A. developability of cone pairs in every case (analytic K, OpenMesh angle defect at
 *     interior vertices of a grid whose vertices lie on rulings, vtkCurvatures) and normal
 *     continuity across the shared rulings;
 *  B. approximation of the tangent surfaces of a twisted cubic and a helix: pieces against
 *     tolerance, observed order, and the distance of the surface to the analytic input;
 *  C. osculating cone splines against Hermite cone pairs at (nearly) equal piece counts;
 *  D. isometry of the development and of a bending stage: ruling lengths, boundary lengths,
 *     angles between rulings and boundaries; planarity and no overlaps of the development;
 *  E. offsets: every point at distance |d| along the normal.
 */
// These tests call the deprecated wrappers on purpose (they keep working): no warning.
#define RMF_DEPRECATED(note)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "surface_checks.hpp"

extern "C" {
#include "rmf_check.h"
}

using rmf_checks::check_surface;
using rmf_checks::print_report;
using rmf_checks::SurfaceReport;


/* ---- analytic curves: point, first and second derivative ---- */

struct Curve {
    const char *name;
    double t0, t1;
    std::function<void(double, RmfVec3 *, RmfVec3 *, RmfVec3 *)> jet;
};

static Curve twisted_cubic() {
    return Curve{"twisted cubic", 0.2, 1.2, [](double t, RmfVec3 *p, RmfVec3 *d1, RmfVec3 *d2) {
                     *p = vec3(t, t * t, t * t * t);
                     *d1 = vec3(1, 2 * t, 3 * t * t);
                     *d2 = vec3(0, 2, 6 * t);
                 }};
}

static Curve helix() {
    return Curve{"helix r=1 c=0.5", 0.0, M_PI, [](double t, RmfVec3 *p, RmfVec3 *d1, RmfVec3 *d2) {
                     *p = vec3(cos(t), sin(t), 0.5 * t);
                     *d1 = vec3(-sin(t), cos(t), 0.5);
                     *d2 = vec3(-cos(t), -sin(t), 0);
                 }};
}

extern "C" void curve_callback(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    RmfVec3 d2;
    static_cast<const Curve *>(user)->jet(t, point, tangent, &d2);
}

/* The element of the tangent surface at t, distance v > 0 from the curve. */
static RmfConeElement element(const Curve &c, double t, double v) {
    RmfVec3 p, d1, d2;
    c.jet(t, &p, &d1, &d2);
    const RmfVec3 e = ne_unit(d1);
    return RmfConeElement{ne_add(p, ne_scale(e, v)), e, ne_unit(ne_add(d2, ne_scale(e, -ne_dot(d2, e))))};
}

/* Distance from y to the sheet v > 0 of the tangent surface: the nearest ruling over t,
 * scanned and refined by golden sections. */
static double distance_to_tangent_surface(const Curve &c, RmfVec3 y) {
    auto d = [&](double t) {
        RmfVec3 p, d1, d2;
        c.jet(t, &p, &d1, &d2);
        const RmfVec3 e = ne_unit(d1), w = ne_add(y, ne_scale(p, -1));
        return ne_dot(w, e) > 0 ? ne_norm(ne_cross(w, e)) : 1e300;
    };
    const int n = 400;
    int best = 0;
    for (int k = 1; k <= n; ++k)
        if (d(c.t0 + (c.t1 - c.t0) * k / n) < d(c.t0 + (c.t1 - c.t0) * best / n)) best = k;
    double a = c.t0 + (c.t1 - c.t0) * std::max(best - 1, 0) / n, b = c.t0 + (c.t1 - c.t0) * std::min(best + 1, n) / n;
    const double g = 0.5 * (sqrt(5.0) - 1);
    for (int it = 0; it < 100; ++it) {
        const double x1 = b - g * (b - a), x2 = a + g * (b - a);
        if (d(x1) < d(x2)) b = x2;
        else a = x1;
    }
    return d(0.5 * (a + b));
}

/* ---- the NURBS and Bézier views ---- */

static RmfSurface *strip(RmfConeSpline *spline, double t0, double t1) {
    RmfSurface *s = nullptr;
    CHECK_STATUS(rmf_cone_spline_surface(spline, t0, t1, &s), RMF_OK, "");
    return s;
}

/* Point and first partials of a rational Bézier patch view at local (s, t). */
static void patch_jet(const RmfBezierPatch &b, double s, double t, RmfVec3 &p, RmfVec3 &du, RmfVec3 &dv) {
    auto bern = [](int n, int i, double x, double &value, double &deriv) {
        auto c = [](int n, int k) {
            double r = 1;
            for (int j = 1; j <= k; ++j) r = r * (n - k + j) / j;
            return r;
        };
        auto B = [&](int m, int k) { return (k < 0 || k > m) ? 0.0 : c(m, k) * pow(x, k) * pow(1 - x, m - k); };
        value = B(n, i);
        deriv = n * (B(n - 1, i - 1) - B(n - 1, i));
    };
    double h[4] = {0, 0, 0, 0}, hu[4] = {0, 0, 0, 0}, hv[4] = {0, 0, 0, 0};
    const int nu = (int)b.degree_u, nv = (int)b.degree_v;
    for (int i = 0; i <= nu; ++i)
        for (int j = 0; j <= nv; ++j) {
            double bi, dbi, bj, dbj;
            bern(nu, i, s, bi, dbi);
            bern(nv, j, t, bj, dbj);
            const RmfVec3 q = b.poles[i * (nv + 1) + j];
            const double w = b.weights[i * (nv + 1) + j], c4[4] = {w * q.x, w * q.y, w * q.z, w};
            for (int k = 0; k < 4; ++k) {
                h[k] += bi * bj * c4[k];
                hu[k] += dbi * bj * c4[k];
                hv[k] += bi * dbj * c4[k];
            }
        }
    p = vec3(h[0] / h[3], h[1] / h[3], h[2] / h[3]);
    du = ne_scale(vec3(hu[0] - hu[3] * p.x, hu[1] - hu[3] * p.y, hu[2] - hu[3] * p.z), 1 / h[3]);
    dv = ne_scale(vec3(hv[0] - hv[3] * p.x, hv[1] - hv[3] * p.y, hv[2] - hv[3] * p.z), 1 / h[3]);
}

/* Largest angle between the normals of neighbouring patches along their shared rulings. */
static double normal_jump(RmfSurface *surface) {
    size_t nu = 0, nv = 0;
    rmf_surface_patch_count(surface, &nu, &nv);
    double worst = 0;
    for (size_t b = 0; b + 1 < nv; ++b) {
        RmfBezierPatch left, right;
        rmf_surface_patch(surface, 0, b, &left);
        rmf_surface_patch(surface, 0, b + 1, &right);
        for (int k = 0; k <= 10; ++k) {
            RmfVec3 p, q, lu, lv, ru, rv;
            patch_jet(left, k / 10.0, 1.0, p, lu, lv);
            patch_jet(right, k / 10.0, 0.0, q, ru, rv);
            const RmfVec3 a = ne_unit(ne_cross(lu, lv)), c = ne_unit(ne_cross(ru, rv));
            CHECK(ne_dist(p, q) < 1e-12 * (1 + ne_norm(p)), "patches share the ruling");
            worst = std::max(worst, atan2(ne_norm(ne_cross(a, c)), ne_dot(a, c)));
        }
    }
    return worst;
}

/* Developability and G1 of one cone spline strip. */
static void check_developable(const char *name, RmfConeSpline *spline, double t0, double t1) {
    RmfSurface *s = strip(spline, t0, t1);
    if (!s) return;
    RmfNurbsSurface view;
    CHECK_STATUS(rmf_surface_nurbs(s, &view), RMF_OK, "");
    const SurfaceReport r = check_surface(view, 6, 8);
    const double jump = normal_jump(s);
    print_report(name, r);
    std::printf("%-28s normals across shared rulings: max jump %.3e rad\n", "", jump);
    CHECK(r.interior_vertices > 50, "enough interior vertices");
    CHECK(r.max_k_analytic < 1e-9, "analytic K = 0 to round-off");
    CHECK(r.max_defect <= 1e-9, "OpenMesh angle defect <= 1e-9 at interior vertices");
    CHECK(r.max_k_vtk < 1e-6, "vtkCurvatures K = 0");
    CHECK(jump < 1e-9, "normals continuous across shared rulings to 1e-9 rad");
    rmf_surface_free(s);
}

static RmfConeSpline *hermite(const std::vector<RmfConeElement> &els, uint32_t rule = RMF_CONE_RULE_MIN_VERTEX_DISTANCE) {
    RmfConeSpline *spline = nullptr;
    CHECK_STATUS(rmf_cone_spline_hermite(els.data(), els.size(), rule, 0, nullptr, &spline), RMF_OK, "");
    return spline;
}

static std::vector<RmfConeElement> tangent_elements(const Curve &c, int n, double v) {
    std::vector<RmfConeElement> els;
    for (int i = 0; i < n; ++i) els.push_back(element(c, c.t0 + (c.t1 - c.t0) * i / (n - 1), v));
    return els;
}

static uint32_t first_case(RmfConeSpline *s) {
    RmfConePiece piece;
    rmf_cone_spline_piece(s, 0, &piece);
    return piece.pair_case;
}

static void section_a_cases() {
    std::printf("A. developability and G1 of cone pairs in every case\n");
    RmfConeSpline *general = hermite(tangent_elements(twisted_cubic(), 6, 3.5));
    if (general) {
        CHECK(first_case(general) == RMF_CONE_CASE_GENERAL, "general case");
        check_developable("general (twisted cubic)", general, -0.4, 0.4);
    }
    RmfConeSpline *slope = hermite(tangent_elements(helix(), 5, 5.0));
    if (slope) {
        CHECK(first_case(slope) == RMF_CONE_CASE_CONSTANT_SLOPE, "constant-slope case");
        check_developable("constant slope (helix)", slope, -0.4, 0.4);
    }
    /* An elliptic cone x²/4 + y² = z² and an elliptic cylinder x²/4 + y² = 1. */
    std::vector<RmfConeElement> cone, cylinder;
    for (int i = 0; i < 5; ++i) {
        const double s = 0.3 * i;
        const RmfVec3 ruling = ne_unit(vec3(2 * cos(s), sin(s), 1)), tangent = vec3(-2 * sin(s), cos(s), 0);
        cone.push_back(RmfConeElement{ne_scale(ruling, 2.0), ruling, ne_unit(ne_add(tangent, ne_scale(ruling, -ne_dot(tangent, ruling))))});
        cylinder.push_back(RmfConeElement{vec3(2 * cos(s), sin(s), 0), vec3(0, 0, 1), ne_unit(tangent)});
    }
    RmfConeSpline *c = hermite(cone), *y = hermite(cylinder);
    if (c) {
        CHECK(first_case(c) == RMF_CONE_CASE_CONE, "cone case");
        check_developable("cone case (elliptic cone)", c, -0.5, 0.5);
    }
    if (y) {
        CHECK(first_case(y) == RMF_CONE_CASE_CYLINDER, "cylinder case");
        check_developable("cylinder case", y, -0.5, 0.5);
    }
    RmfConeSpline *first_cylinder = hermite(tangent_elements(twisted_cubic(), 4, 3.5), RMF_CONE_RULE_CYLINDER_FIRST);
    if (first_cylinder) check_developable("cylinder-first rule", first_cylinder, -0.4, 0.4);
    rmf_cone_spline_free(general);
    rmf_cone_spline_free(slope);
    rmf_cone_spline_free(c);
    rmf_cone_spline_free(y);
    rmf_cone_spline_free(first_cylinder);
}

/* Largest distance from the strip's sampled NURBS points to the analytic tangent surface. */
static double strip_distance(const Curve &curve, RmfConeSpline *spline, double t0, double t1) {
    RmfSurface *s = strip(spline, t0, t1);
    if (!s) return 1e300;
    RmfNurbsSurface view;
    rmf_surface_nurbs(s, &view);
    const double v_end = view.knots_v[view.knot_count_v - 1];
    double worst = 0;
    for (int i = 0; i <= 4; ++i)
        for (int j = 0; j <= 400; ++j) {
            RmfVec3 d[3][3];
            ne_surface_derivatives(&view, t0 + (t1 - t0) * i / 4.0, v_end * j / 400.0, d);
            worst = std::max(worst, distance_to_tangent_surface(curve, d[0][0]));
        }
    rmf_surface_free(s);
    return worst;
}

static void section_b_approximation() {
    std::printf("B. approximating tangent surfaces (region v in [0.5, 8] from the curve; strip +-0.2 checked)\n");
    for (Curve curve : {twisted_cubic(), helix()}) {
        std::vector<double> logs_tol, logs_n;
        for (double tol : {1e-2, 1e-3, 1e-4, 1e-5}) {
            RmfConeSpline *spline = nullptr;
            double max_error = -1;
            size_t pieces = 0;
            CHECK_STATUS(rmf_cone_spline_approximate(nullptr, curve_callback, &curve, curve.t0, curve.t1, 0.5, 8.0, tol,
                                                     RMF_CONE_RULE_MIN_VERTEX_DISTANCE, 100000, &spline, &max_error),
                         RMF_OK, "");
            if (!spline) continue;
            rmf_cone_spline_piece_count(spline, &pieces);
            /* The reference point v = 4.25 drifts with the arc length along the parallel circles. */
            const double independent = strip_distance(curve, spline, -0.2, 0.2);
            std::printf("  %-18s tolerance %.0e: %4zu pieces, library max deviation %.3e, surface-to-input %.3e\n",
                        curve.name, tol, pieces, max_error, independent);
            CHECK(max_error <= tol, "the library's sampled deviation is within the tolerance");
            CHECK(independent <= tol, "every sampled surface point is within the tolerance of the input");
            logs_tol.push_back(log(1 / tol));
            logs_n.push_back(log((double)pieces));
            rmf_cone_spline_free(spline);
        }
        /* Least-squares slope of log(pieces) over log(1/tol): pieces ~ tol^(-1/order). */
        const size_t n = logs_tol.size();
        double mx = 0, my = 0, sxx = 0, sxy = 0;
        if (n < 2) continue;
        for (size_t k = 0; k < n; ++k) mx += logs_tol[k] / n, my += logs_n[k] / n;
        for (size_t k = 0; k < n; ++k) sxx += pow(logs_tol[k] - mx, 2), sxy += (logs_tol[k] - mx) * (logs_n[k] - my);
        const double order = sxx / sxy;
        std::printf("  %-18s observed approximation order (error ~ h^order) %.2f\n", curve.name, order);
        CHECK(order > 2.5, "at least third order");
    }
}

static void section_c_osculating() {
    std::printf("C. osculating cone splines against Hermite cone pairs (twisted cubic, strip +-0.2)\n");
    Curve curve = twisted_cubic();
    for (int cones : {8, 11, 16, 21}) {
        std::vector<double> ts;
        for (int i = 0; i < cones; ++i) ts.push_back(curve.t0 + (curve.t1 - curve.t0) * i / (cones - 1));
        RmfConeSpline *osc = nullptr;
        CHECK_STATUS(rmf_cone_spline_osculating(nullptr, curve_callback, &curve, curve.t0, curve.t1, 0.5, 6.0, ts.data(),
                                                ts.size(), &osc),
                     RMF_OK, "");
        if (!osc) continue;
        size_t pieces = 0;
        rmf_cone_spline_piece_count(osc, &pieces);
        const double e_osc = strip_distance(curve, osc, -0.2, 0.2);
        double e_h[2];
        size_t n_h[2];
        for (int k = 0; k < 2; ++k) {
            RmfConeSpline *h = hermite(tangent_elements(curve, (int)pieces / 2 + k, 3.25));
            if (!h) continue;
            rmf_cone_spline_piece_count(h, &n_h[k]);
            e_h[k] = strip_distance(curve, h, -0.2, 0.2);
            rmf_cone_spline_free(h);
        }
        std::printf("  %2d osculating cones: %2zu pieces, max distance %.3e | Hermite pairs: %2zu pieces %.3e, %2zu pieces %.3e\n",
                    cones, pieces, e_osc, n_h[0], e_h[0], n_h[1], e_h[1]);
        CHECK(e_osc < 1e-3, "the osculating cone spline approximates the surface");
        check_developable("  osculating cone spline", osc, -0.2, 0.2);
        rmf_cone_spline_free(osc);
    }
}

/* ---- D: isometry ---- */

struct Measures {
    std::vector<double> rulings, boundaries, angles;
};

static Measures measure(RmfConeSpline *spline, double t0, double t1) {
    Measures m;
    RmfSurface *s = strip(spline, t0, t1);
    if (!s) return m;
    RmfNurbsSurface view;
    rmf_surface_nurbs(s, &view);
    std::vector<double> knots(view.knots_v, view.knots_v + view.knot_count_v);
    knots.erase(std::unique(knots.begin(), knots.end()), knots.end());
    static const double gx[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                                 0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
    static const double gw[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                                 0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    for (double t : {t0, t1}) {
        double length = 0;
        for (size_t k = 0; k + 1 < knots.size(); ++k)
            for (int sub = 0; sub < 8; ++sub) {
                const double a = knots[k] + (knots[k + 1] - knots[k]) * sub / 8.0, h = (knots[k + 1] - knots[k]) / 8.0;
                for (int g = 0; g < 8; ++g) {
                    RmfVec3 d[3][3];
                    ne_surface_derivatives(&view, t, a + h * 0.5 * (gx[g] + 1), d);
                    length += 0.5 * h * gw[g] * ne_norm(d[0][1]);
                }
            }
        m.boundaries.push_back(length);
    }
    for (size_t k = 0; k < knots.size(); ++k) {
        RmfVec3 a[3][3], b[3][3];
        ne_surface_derivatives(&view, t0, knots[k], a);
        ne_surface_derivatives(&view, t1, knots[k], b);
        m.rulings.push_back(ne_dist(a[0][0], b[0][0]));
        for (double v : {knots[k], k + 1 < knots.size() ? 0.5 * (knots[k] + knots[k + 1]) : knots[k]})
            for (double t : {t0, t1}) {
                RmfVec3 d[3][3];
                ne_surface_derivatives(&view, t, v, d);
                m.angles.push_back(atan2(ne_norm(ne_cross(d[1][0], d[0][1])), ne_dot(d[1][0], d[0][1])));
            }
    }
    rmf_surface_free(s);
    return m;
}

static double worst_relative(const std::vector<double> &a, const std::vector<double> &b) {
    double w = 0;
    for (size_t k = 0; k < a.size(); ++k) w = std::max(w, fabs(a[k] - b[k]) / std::max(fabs(a[k]), 1e-300));
    return w;
}

static bool segments_cross(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
    auto orient = [](double px, double py, double qx, double qy, double rx, double ry) {
        return (qx - px) * (ry - py) - (qy - py) * (rx - px);
    };
    const double o1 = orient(ax, ay, bx, by, cx, cy), o2 = orient(ax, ay, bx, by, dx, dy);
    const double o3 = orient(cx, cy, dx, dy, ax, ay), o4 = orient(cx, cy, dx, dy, bx, by);
    return o1 * o2 < 0 && o3 * o4 < 0;
}

/* Planarity and no overlaps: z = 0, all triangles of the grid turn the same way, and the
 * boundary polygon does not cross itself (then the developed strip is embedded). */
static void check_flat(const char *name, RmfConeSpline *flat, double t0, double t1) {
    RmfSurface *s = strip(flat, t0, t1);
    if (!s) return;
    RmfNurbsSurface view;
    rmf_surface_nurbs(s, &view);
    std::vector<double> knots(view.knots_v, view.knots_v + view.knot_count_v);
    knots.erase(std::unique(knots.begin(), knots.end()), knots.end());
    const int su = 4, sv = 16;
    std::vector<double> vs;
    for (size_t k = 0; k + 1 < knots.size(); ++k)
        for (int j = 0; j < sv; ++j) vs.push_back(knots[k] + (knots[k + 1] - knots[k]) * j / sv);
    vs.push_back(knots.back());
    std::vector<std::vector<RmfVec3>> grid(su + 1, std::vector<RmfVec3>(vs.size()));
    double max_z = 0;
    for (int i = 0; i <= su; ++i)
        for (size_t j = 0; j < vs.size(); ++j) {
            RmfVec3 d[3][3];
            ne_surface_derivatives(&view, t0 + (t1 - t0) * i / su, vs[j], d);
            grid[i][j] = d[0][0];
            max_z = std::max(max_z, fabs(d[0][0].z));
        }
    int positive = 0, negative = 0;
    for (int i = 0; i < su; ++i)
        for (size_t j = 0; j + 1 < vs.size(); ++j) {
            const RmfVec3 a = grid[i][j], b = grid[i + 1][j], c = grid[i + 1][j + 1], d = grid[i][j + 1];
            const double z1 = ne_cross(ne_add(b, ne_scale(a, -1)), ne_add(c, ne_scale(a, -1))).z;
            const double z2 = ne_cross(ne_add(c, ne_scale(a, -1)), ne_add(d, ne_scale(a, -1))).z;
            (z1 > 0 ? positive : negative)++;
            (z2 > 0 ? positive : negative)++;
        }
    std::vector<RmfVec3> polygon;
    for (size_t j = 0; j < vs.size(); ++j) polygon.push_back(grid[0][j]);
    for (int i = 1; i <= su; ++i) polygon.push_back(grid[i][vs.size() - 1]);
    for (size_t j = vs.size() - 1; j-- > 0;) polygon.push_back(grid[su][j]);
    for (int i = su - 1; i > 0; --i) polygon.push_back(grid[i][0]);
    size_t crossings = 0;
    const size_t m = polygon.size();
    for (size_t a = 0; a < m; ++a)
        for (size_t b = a + 2; b < m; ++b) {
            if (a == 0 && b == m - 1) continue;
            const RmfVec3 p = polygon[a], q = polygon[(a + 1) % m], r = polygon[b], t = polygon[(b + 1) % m];
            crossings += segments_cross(p.x, p.y, q.x, q.y, r.x, r.y, t.x, t.y);
        }
    std::printf("  %-26s development: max |z| %.1e, triangles %d/%d one orientation, boundary self-crossings %zu\n", name,
                max_z, std::max(positive, negative), positive + negative, crossings);
    CHECK(max_z < 1e-12, "the development lies in z = 0");
    CHECK(positive == 0 || negative == 0, "no folded triangle");
    CHECK(crossings == 0, "the developed boundary does not cross itself: no overlaps");
    rmf_surface_free(s);
}

static void section_d_development() {
    std::printf("D. isometry of the development and of the bending stage s = 0.5\n");
    struct Case {
        const char *name;
        RmfConeSpline *spline;
    } cases[2] = {{"twisted cubic pairs", hermite(tangent_elements(twisted_cubic(), 6, 3.5))},
                  {"helix pairs", hermite(tangent_elements(helix(), 5, 5.0))}};
    for (const Case &c : cases) {
        if (!c.spline) continue;
        const double t0 = -0.4, t1 = 0.4;
        const Measures original = measure(c.spline, t0, t1);
        RmfConeSpline *flat = nullptr, *bent = nullptr;
        CHECK_STATUS(rmf_cone_spline_develop(c.spline, &flat), RMF_OK, "");
        CHECK_STATUS(rmf_cone_spline_bend(c.spline, 0.5, &bent), RMF_OK, "");
        for (RmfConeSpline *image : {flat, bent}) {
            if (!image) continue;
            const Measures m = measure(image, t0, t1);
            const double er = worst_relative(original.rulings, m.rulings), eb = worst_relative(original.boundaries, m.boundaries),
                         ea = worst_relative(original.angles, m.angles);
            std::printf("  %-26s %-11s relative errors: ruling lengths %.1e, boundary lengths %.1e, angles %.1e\n", c.name,
                        image == flat ? "development" : "s = 0.5", er, eb, ea);
            CHECK(er <= 1e-9 && eb <= 1e-9 && ea <= 1e-9, "isometric to 1e-9 relative");
        }
        if (flat) check_flat(c.name, flat, t0, t1);
        if (bent) check_developable("  bending stage s = 0.5", bent, t0, t1);
        rmf_cone_spline_free(flat);
        rmf_cone_spline_free(bent);
        rmf_cone_spline_free(c.spline);
    }
}

static void section_e_offsets() {
    std::printf("E. offsets\n");
    RmfConeSpline *spline = hermite(tangent_elements(twisted_cubic(), 6, 3.5));
    if (!spline) return;
    for (double d : {0.15, -0.1}) {
        RmfConeSpline *off = nullptr;
        CHECK_STATUS(rmf_cone_spline_offset(spline, d, &off), RMF_OK, "");
        RmfSurface *a = strip(spline, -0.4, 0.4), *b = strip(off, -0.4, 0.4);
        if (!a || !b) {
            rmf_surface_free(a);
            rmf_surface_free(b);
            rmf_cone_spline_free(off);
            continue;
        }
        RmfNurbsSurface va, vb;
        rmf_surface_nurbs(a, &va);
        rmf_surface_nurbs(b, &vb);
        double worst_distance = 0, worst_direction = 0;
        const double v_end = va.knots_v[va.knot_count_v - 1];
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 300; ++j) {
                RmfVec3 p[3][3], q[3][3];
                const double u = -0.4 + 0.1 * i, v = v_end * j / 300.0;
                ne_surface_derivatives(&va, u, v, p);
                ne_surface_derivatives(&vb, u, v, q);
                const RmfVec3 gap = ne_add(q[0][0], ne_scale(p[0][0], -1)), n = ne_unit(ne_cross(p[1][0], p[0][1]));
                worst_distance = std::max(worst_distance, fabs(ne_norm(gap) - fabs(d)));
                worst_direction = std::max(worst_direction, ne_norm(ne_cross(gap, n)));
            }
        std::printf("  offset d = %+.2f: max | |S_d - S| - |d| | = %.1e, max |(S_d - S) x N| = %.1e\n", d, worst_distance,
                    worst_direction);
        CHECK(worst_distance < 1e-12 && worst_direction < 1e-12, "every offset point is at distance |d| along the normal");
        rmf_surface_free(a);
        rmf_surface_free(b);
        rmf_cone_spline_free(off);
    }
    rmf_cone_spline_free(spline);
}

int main() {
    std::setvbuf(stdout, nullptr, _IONBF, 0);
    section_a_cases();
    section_b_approximation();
    section_c_osculating();
    section_d_development();
    section_e_offsets();
    return rmf_check_exit_code("geometry_cone_spline");
}
