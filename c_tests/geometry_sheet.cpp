/*
 * Independent geometry checks of sheet-metal parts (issue 15), from the exported NURBS
 * and the DXF text only — the suite's own NURBS evaluator, its own DXF reader, OpenMesh
 * and VTK — on the square-to-round hopper of examples/cli/hopper.json (square 200 × 200
 * at z = 0, circle of radius 60 about (20, 0, 150), thickness 2, K-factor 0.4):
 *
 *  A. the part's edges against the input square and circle (≤ the tolerance);
 *  B. developability: max |K|·size² of the designed surface and of the neutral layer,
 *     analytic from the NURBS, OpenMesh angle defects and vtkCurvatures (interior rows: the
 *     rows at the corner cones' vertices are singular);
 *  C. the DXF flat pattern: chained into a closed loop from its LINE and ARC entities, its
 *     area by Green's theorem against the formed neutral layer's area by Gauss–Legendre
 *     quadrature, and the lengths of its edges (bottom, top, seam) against the formed ones;
 *  D. marks: 1,000 random flat points to the surface and back, points on the NURBS, and
 *     flat segments against the lengths of their images (geodesics);
 *  E. pieces per tolerance 1e-2 … 1e-5.
 */
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "surface_checks.hpp"

extern "C" {
#include "rmf_check.h"
}

using rmf_checks::check_surface_at;
using rmf_checks::print_report;
using rmf_checks::SurfaceReport;

static const double GX[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                             0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
static const double GW[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                             0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

static RmfCurve *square_curve() {
    const RmfVec3 poles[5] = {vec3(-100, -100, 0), vec3(100, -100, 0), vec3(100, 100, 0), vec3(-100, 100, 0),
                              vec3(-100, -100, 0)};
    const double knots[7] = {0, 0, 1, 2, 3, 4, 4};
    RmfCurve *c = nullptr;
    CHECK_STATUS(rmf_nurbs_curve_create(1, poles, nullptr, 5, knots, 7, &c), RMF_OK, "");
    return c;
}

static RmfCurve *circle_curve() {
    const double xs[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, ys[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    const double knots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    RmfVec3 poles[9];
    double weights[9];
    for (int i = 0; i < 9; ++i) {
        poles[i] = vec3(20 + 60 * xs[i], 60 * ys[i], 150);
        weights[i] = i % 2 ? std::sqrt(0.5) : 1.0;
    }
    RmfCurve *c = nullptr;
    CHECK_STATUS(rmf_nurbs_curve_create(2, poles, weights, 9, knots, 12, &c), RMF_OK, "");
    return c;
}

static RmfSheetPart *hopper(double tolerance) {
    RmfCurve *bottom = square_curve(), *top = circle_curve();
    RmfSheetOptions o;
    rmf_sheet_options_init(&o);
    o.tolerance = tolerance;
    o.thickness = 2;
    o.k_factor = 0.4;
    RmfSheetPart *part = nullptr;
    CHECK_STATUS(rmf_sheet_part_transition(bottom, top, &o, &part), RMF_OK, "");
    rmf_curve_free(bottom);
    rmf_curve_free(top);
    return part;
}

/* Distinct knots. */
static std::vector<double> breaks(const double *knots, size_t n) {
    std::vector<double> b(knots, knots + n);
    b.erase(std::unique(b.begin(), b.end()), b.end());
    return b;
}

static double segment_distance(RmfVec3 p, RmfVec3 a, RmfVec3 b) {
    const RmfVec3 d = ne_sub(b, a);
    const double s = std::min(1.0, std::max(0.0, ne_dot(ne_sub(p, a), d) / ne_dot(d, d)));
    return ne_dist(p, ne_add(a, ne_scale(d, s)));
}

static double square_distance(RmfVec3 p) {
    const RmfVec3 c[4] = {vec3(-100, -100, 0), vec3(100, -100, 0), vec3(100, 100, 0), vec3(-100, 100, 0)};
    double d = 1e300;
    for (int k = 0; k < 4; ++k) d = std::min(d, segment_distance(p, c[k], c[(k + 1) % 4]));
    return d;
}

static double circle_distance(RmfVec3 p) { return std::hypot(std::hypot(p.x - 20, p.y) - 60, p.z - 150); }

/* Largest distance of a boundary curve (sampled in every knot span) from an input curve. */
static double edge_distance(RmfSheetPart *part, uint32_t side, double (*distance)(RmfVec3)) {
    RmfCurve *edge = nullptr;
    CHECK_STATUS(rmf_sheet_part_boundary(part, RMF_SHEET_LAYER_REFERENCE, side, &edge), RMF_OK, "");
    if (!edge) return 1e300;
    RmfNurbsCurve view;
    rmf_curve_nurbs(edge, &view);
    const std::vector<double> b = breaks(view.knots, view.knot_count);
    double worst = 0;
    for (size_t k = 0; k + 1 < b.size(); ++k)
        for (int j = 0; j <= 16; ++j) {
            RmfVec3 d[3];
            ne_curve_derivatives(&view, b[k] + (b[k + 1] - b[k]) * j / 16.0, d);
            worst = std::max(worst, distance(d[0]));
        }
    rmf_curve_free(edge);
    return worst;
}

/* Length of a layer's boundary by Gauss–Legendre quadrature per knot span. */
static double boundary_length(RmfSheetPart *part, uint32_t layer, uint32_t side) {
    RmfCurve *edge = nullptr;
    CHECK_STATUS(rmf_sheet_part_boundary(part, layer, side, &edge), RMF_OK, "");
    if (!edge) return 0;
    RmfNurbsCurve view;
    rmf_curve_nurbs(edge, &view);
    const std::vector<double> b = breaks(view.knots, view.knot_count);
    double length = 0;
    for (size_t k = 0; k + 1 < b.size(); ++k)
        for (int sub = 0; sub < 4; ++sub) {
            const double h = (b[k + 1] - b[k]) / 4, a = b[k] + sub * h;
            for (int g = 0; g < 8; ++g) {
                RmfVec3 d[3];
                ne_curve_derivatives(&view, a + h * 0.5 * (GX[g] + 1), d);
                length += 0.5 * h * GW[g] * ne_norm(d[1]);
            }
        }
    rmf_curve_free(edge);
    return length;
}

/* The NURBS view of a layer (the surface handle is returned for freeing). */
static RmfSurface *layer_surface(RmfSheetPart *part, uint32_t layer, RmfNurbsSurface *view) {
    RmfSurface *s = nullptr;
    CHECK_STATUS(rmf_sheet_part_surface(part, layer, &s), RMF_OK, "");
    if (s) CHECK_STATUS(rmf_surface_nurbs(s, view), RMF_OK, "");
    return s;
}

static double surface_area(const RmfNurbsSurface &view) {
    const std::vector<double> bu = breaks(view.knots_u, view.knot_count_u), bv = breaks(view.knots_v, view.knot_count_v);
    double area = 0;
    for (size_t a = 0; a + 1 < bu.size(); ++a)
        for (size_t b = 0; b + 1 < bv.size(); ++b)
            for (int i = 0; i < 8; ++i)
                for (int j = 0; j < 8; ++j) {
                    const double hu = bu[a + 1] - bu[a], hv = bv[b + 1] - bv[b];
                    RmfVec3 d[3][3];
                    ne_surface_derivatives(&view, bu[a] + hu * 0.5 * (GX[i] + 1), bv[b] + hv * 0.5 * (GX[j] + 1), d);
                    area += 0.25 * hu * hv * GW[i] * GW[j] * ne_norm(ne_cross(d[1][0], d[0][1]));
                }
    return area;
}

/* ---- the DXF reader ---- */

struct DxfEdge {
    bool arc;
    double ax, ay, bx, by;                 /* ends (an arc: counter-clockwise from a to b) */
    double cx, cy, r, sweep;               /* arcs only, sweep > 0 */
    double length() const { return arc ? r * sweep : std::hypot(bx - ax, by - ay); }
};

/* The LINE and ARC entities of `layer` in a DXF R12 text (group code / value pairs). */
static std::vector<DxfEdge> read_dxf(const std::string &text, const char *layer) {
    std::vector<std::pair<int, std::string>> pairs;
    size_t pos = 0;
    while (pos < text.size()) {
        const size_t e1 = text.find('\n', pos), e2 = text.find('\n', e1 + 1);
        if (e1 == std::string::npos || e2 == std::string::npos) break;
        pairs.emplace_back(std::atoi(text.substr(pos, e1 - pos).c_str()), text.substr(e1 + 1, e2 - e1 - 1));
        pos = e2 + 1;
    }
    std::vector<DxfEdge> edges;
    for (size_t k = 0; k < pairs.size(); ++k) {
        if (pairs[k].first != 0 || (pairs[k].second != "LINE" && pairs[k].second != "ARC")) continue;
        const bool arc = pairs[k].second == "ARC";
        double v[64] = {0};
        std::string on;
        for (size_t j = k + 1; j < pairs.size() && pairs[j].first != 0; ++j) {
            if (pairs[j].first == 8) on = pairs[j].second;
            else if (pairs[j].first < 64) v[pairs[j].first] = std::strtod(pairs[j].second.c_str(), nullptr);
        }
        if (on != layer) continue;
        DxfEdge e{};
        e.arc = arc;
        if (arc) {
            e.cx = v[10], e.cy = v[20], e.r = v[40];
            const double a0 = v[50] * M_PI / 180, a1 = v[51] * M_PI / 180;
            e.sweep = std::fmod(a1 - a0 + 4 * M_PI, 2 * M_PI);
            e.ax = e.cx + e.r * std::cos(a0), e.ay = e.cy + e.r * std::sin(a0);
            e.bx = e.cx + e.r * std::cos(a1), e.by = e.cy + e.r * std::sin(a1);
        } else {
            e.ax = v[10], e.ay = v[20], e.bx = v[11], e.by = v[21];
        }
        edges.push_back(e);
    }
    return edges;
}

/* The edges chained into one loop (each reversed where needed): index and direction. */
struct Chained {
    std::vector<std::pair<size_t, bool>> order; /* (edge, forward) */
    bool closed = false;
};

static Chained chain(const std::vector<DxfEdge> &edges, double tol) {
    Chained c;
    std::vector<bool> used(edges.size(), false);
    if (edges.empty()) return c;
    c.order.push_back({0, true});
    used[0] = true;
    double x = edges[0].bx, y = edges[0].by;
    for (size_t step = 1; step < edges.size(); ++step) {
        bool found = false;
        for (size_t k = 0; k < edges.size() && !found; ++k) {
            if (used[k]) continue;
            const DxfEdge &e = edges[k];
            if (std::hypot(e.ax - x, e.ay - y) <= tol) {
                c.order.push_back({k, true}), x = e.bx, y = e.by, found = true;
            } else if (std::hypot(e.bx - x, e.by - y) <= tol) {
                c.order.push_back({k, false}), x = e.ax, y = e.ay, found = true;
            }
            if (found) used[k] = true;
        }
        if (!found) return c;
    }
    c.closed = std::hypot(x - edges[0].ax, y - edges[0].ay) <= tol;
    return c;
}

/* Signed area of the chained loop by Green's theorem: chords plus circular segments. */
static double loop_area(const std::vector<DxfEdge> &edges, const Chained &c) {
    double twice = 0;
    for (const auto &[k, forward] : c.order) {
        const DxfEdge &e = edges[k];
        const double ax = forward ? e.ax : e.bx, ay = forward ? e.ay : e.by;
        const double bx = forward ? e.bx : e.ax, by = forward ? e.by : e.ay;
        twice += ax * by - bx * ay;
        if (e.arc) twice += (forward ? 1 : -1) * e.r * e.r * (e.sweep - std::sin(e.sweep));
    }
    return 0.5 * twice;
}

/* Points along the loop, for the point-in-polygon test of the marks. */
static std::vector<std::pair<double, double>> polygonize(const std::vector<DxfEdge> &edges, const Chained &c) {
    std::vector<std::pair<double, double>> p;
    for (const auto &[k, forward] : c.order) {
        const DxfEdge &e = edges[k];
        const int n = e.arc ? 16 : 1;
        for (int j = 0; j < n; ++j) {
            const double s = forward ? double(j) / n : 1 - double(j) / n;
            if (e.arc) {
                const double a0 = std::atan2(e.ay - e.cy, e.ax - e.cx) + s * e.sweep;
                p.push_back({e.cx + e.r * std::cos(a0), e.cy + e.r * std::sin(a0)});
            } else {
                p.push_back({e.ax + s * (e.bx - e.ax), e.ay + s * (e.by - e.ay)});
            }
        }
    }
    return p;
}

static bool inside(const std::vector<std::pair<double, double>> &poly, double x, double y, double *margin) {
    double winding = 0, nearest = 1e300;
    for (size_t k = 0; k < poly.size(); ++k) {
        const double ax = poly[k].first - x, ay = poly[k].second - y;
        const double bx = poly[(k + 1) % poly.size()].first - x, by = poly[(k + 1) % poly.size()].second - y;
        winding += std::atan2(ax * by - ay * bx, ax * bx + ay * by);
        const double dx = bx - ax, dy = by - ay, s = std::min(1.0, std::max(0.0, -(ax * dx + ay * dy) / (dx * dx + dy * dy)));
        nearest = std::min(nearest, std::hypot(ax + s * dx, ay + s * dy));
    }
    *margin = nearest;
    return std::fabs(winding) > M_PI;
}

/* Distance from p to the surface: the nearest grid point, then Newton on (u, v). */
static double surface_distance(const RmfNurbsSurface &view, RmfVec3 p) {
    const std::vector<double> bu = breaks(view.knots_u, view.knot_count_u), bv = breaks(view.knots_v, view.knot_count_v);
    double best = 1e300, u = 0, v = 0;
    for (size_t b = 0; b + 1 < bv.size(); ++b)
        for (int j = 0; j <= 4; ++j)
            for (int i = 0; i <= 10; ++i) {
                RmfVec3 d[3][3];
                const double uu = bu[0] + (bu.back() - bu[0]) * i / 10.0, vv = bv[b] + (bv[b + 1] - bv[b]) * j / 4.0;
                ne_surface_derivatives(&view, uu, vv, d);
                const double dist = ne_dist(d[0][0], p);
                if (dist < best) best = dist, u = uu, v = vv;
            }
    /* Gauss–Newton with step halving: a step is taken only where it brings the point nearer. */
    auto at = [&](double uu, double vv) {
        RmfVec3 d[3][3];
        ne_surface_derivatives(&view, uu, vv, d);
        return ne_dist(d[0][0], p);
    };
    for (int it = 0; it < 60 && best > 0; ++it) {
        RmfVec3 d[3][3];
        ne_surface_derivatives(&view, u, v, d);
        const RmfVec3 r = ne_sub(d[0][0], p);
        const double a = ne_dot(d[1][0], d[1][0]), b = ne_dot(d[1][0], d[0][1]), c = ne_dot(d[0][1], d[0][1]);
        const double g1 = ne_dot(r, d[1][0]), g2 = ne_dot(r, d[0][1]), det = a * c - b * b;
        if (!(det > 0)) break;
        double du = -(c * g1 - b * g2) / det, dv = -(a * g2 - b * g1) / det;
        bool moved = false;
        for (int half = 0; half < 30 && !moved; ++half, du *= 0.5, dv *= 0.5) {
            const double nu = std::min(bu.back(), std::max(bu[0], u + du)), nv = std::min(bv.back(), std::max(bv[0], v + dv));
            const double dist = at(nu, nv);
            if (dist < best) best = dist, u = nu, v = nv, moved = true;
        }
        if (!moved) break;
    }
    return best;
}

/* The interior grid of a layer: u in [0.02, 0.98], 4 steps per knot span in v. */
static SurfaceReport developability(const RmfNurbsSurface &view) {
    std::vector<double> us, vs;
    for (int i = 0; i <= 12; ++i) us.push_back(0.02 + 0.96 * i / 12.0);
    const std::vector<double> bv = breaks(view.knots_v, view.knot_count_v);
    for (size_t k = 0; k + 1 < bv.size(); ++k)
        for (int j = 0; j < 4; ++j) vs.push_back(bv[k] + (bv[k + 1] - bv[k]) * j / 4.0);
    vs.push_back(bv.back());
    return check_surface_at(view, us, vs);
}

int main() {
    std::setvbuf(stdout, nullptr, _IONBF, 0);
    RmfSheetPart *part = hopper(1e-4);
    if (!part) return rmf_check_exit_code("geometry_sheet");
    RmfSheetReport report;
    rmf_sheet_part_report(part, &report);

    std::printf("A. hopper edges against the input curves (own evaluator), tolerance 1e-4\n");
    const double bottom = edge_distance(part, RMF_SHEET_SIDE_FIRST, square_distance);
    const double top = edge_distance(part, RMF_SHEET_SIDE_SECOND, circle_distance);
    std::printf("  %zu pieces; bottom edge max %.3e from the square, top edge max %.3e from the circle\n", report.pieces,
                bottom, top);
    CHECK(bottom <= 1e-4 && top <= 1e-4, "edges within the tolerance of the input curves");

    std::printf("B. developability (interior rows u in [0.02, 0.98])\n");
    RmfNurbsSurface designed, neutral;
    RmfSurface *s_designed = layer_surface(part, RMF_SHEET_LAYER_REFERENCE, &designed);
    RmfSurface *s_neutral = layer_surface(part, RMF_SHEET_LAYER_NEUTRAL, &neutral);
    if (s_designed && s_neutral) {
        for (const auto &[name, view] : {std::pair<const char *, RmfNurbsSurface &>{"designed surface", designed},
                                         std::pair<const char *, RmfNurbsSurface &>{"neutral layer", neutral}}) {
            const SurfaceReport r = developability(view);
            print_report(name, r);
            CHECK(r.interior_vertices > 1000, "enough interior vertices");
            CHECK(r.max_k_analytic < 1e-9, "analytic K = 0 to round-off");
            CHECK(r.max_defect < 1e-9, "OpenMesh angle defects 0 to round-off");
            CHECK(r.max_k_vtk < 1e-6, "vtkCurvatures K = 0");
        }
    }

    std::printf("C. the DXF flat pattern against the formed neutral layer\n");
    size_t length = 0;
    rmf_sheet_part_export(part, RMF_SHEET_FORMAT_DXF, nullptr, 0, &length);
    std::string dxf(length + 1, '\0');
    CHECK_STATUS(rmf_sheet_part_export(part, RMF_SHEET_FORMAT_DXF, &dxf[0], length + 1, &length), RMF_OK, "");
    dxf.resize(length);
    const std::vector<DxfEdge> cut = read_dxf(dxf, "CUT"), bend = read_dxf(dxf, "BEND");
    const Chained loop = chain(cut, 1e-9);
    CHECK(loop.closed && loop.order.size() == cut.size(), "the CUT entities form one closed loop");
    const double flat_area = loop_area(cut, loop), formed_area = s_neutral ? surface_area(neutral) : 0;
    std::printf("  %zu CUT entities (%zu arcs), %zu BEND lines; area %.9f (from the DXF) vs %.9f (formed neutral "
                "layer, quadrature): relative %.3e\n",
                cut.size(), (size_t)std::count_if(cut.begin(), cut.end(), [](const DxfEdge &e) { return e.arc; }),
                bend.size(), flat_area, formed_area, std::fabs(flat_area - formed_area) / formed_area);
    CHECK(flat_area > 0, "the outline runs counter-clockwise");
    CHECK(std::fabs(flat_area - formed_area) <= 1e-9 * formed_area, "areas agree to 1e-9 relative");
    /* The seam: the two lines as long as the neutral layer's first ruling split the loop
     * into the bottom and the top edge. */
    RmfVec3 d0[3][3], d1[3][3];
    ne_surface_derivatives(&neutral, 0, neutral.knots_v[0], d0);
    ne_surface_derivatives(&neutral, 1, neutral.knots_v[0], d1);
    const double seam = ne_dist(d0[0][0], d1[0][0]);
    std::vector<size_t> seams;
    for (size_t j = 0; j < loop.order.size(); ++j) {
        const DxfEdge &e = cut[loop.order[j].first];
        if (!e.arc && std::fabs(e.length() - seam) <= 1e-9 * seam) seams.push_back(j);
    }
    CHECK(seams.size() == 2, "two seam lines");
    if (seams.size() == 2) {
        double part_a = 0, part_b = 0;
        for (size_t j = seams[0] + 1; j < seams[1]; ++j) part_a += cut[loop.order[j].first].length();
        for (size_t j = seams[1] + 1; j < loop.order.size() + seams[0]; ++j)
            part_b += cut[loop.order[j % loop.order.size()].first].length();
        const double formed_bottom = boundary_length(part, RMF_SHEET_LAYER_NEUTRAL, RMF_SHEET_SIDE_FIRST);
        const double formed_top = boundary_length(part, RMF_SHEET_LAYER_NEUTRAL, RMF_SHEET_SIDE_SECOND);
        /* The longer chain is the square's side. */
        const double flat_bottom = std::max(part_a, part_b), flat_top = std::min(part_a, part_b);
        const double eb = std::fabs(flat_bottom - formed_bottom) / formed_bottom;
        const double et = std::fabs(flat_top - formed_top) / formed_top;
        std::printf("  edge lengths flat vs formed: bottom %.9f vs %.9f (%.1e), top %.9f vs %.9f (%.1e), seam %.9f "
                    "(both seam lines within 1e-9)\n",
                    flat_bottom, formed_bottom, eb, flat_top, formed_top, et, seam);
        CHECK(eb <= 1e-9 && et <= 1e-9, "edge lengths agree to 1e-9 relative");
    }

    std::printf("D. marks: 1,000 random flat points to the surface and back\n");
    const std::vector<std::pair<double, double>> poly = polygonize(cut, loop);
    double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
    for (const auto &p : poly) lo_x = std::min(lo_x, p.first), hi_x = std::max(hi_x, p.first), lo_y = std::min(lo_y, p.second), hi_y = std::max(hi_y, p.second);
    const double size = std::hypot(hi_x - lo_x, hi_y - lo_y);
    std::vector<RmfVec2> flat;
    unsigned seed = 15;
    auto random = [&seed]() { return (seed = seed * 1103515245u + 12345u) / 4294967296.0; };
    while (flat.size() < 1000) {
        const double x = lo_x + (hi_x - lo_x) * random(), y = lo_y + (hi_y - lo_y) * random();
        double margin;
        if (inside(poly, x, y, &margin) && margin > 1.0) flat.push_back(RmfVec2{x, y});
    }
    std::vector<RmfVec3> points(flat.size());
    std::vector<RmfVec2> back(flat.size());
    CHECK_STATUS(rmf_sheet_part_flat_to_surface(part, flat.data(), flat.size(), RMF_SHEET_LAYER_NEUTRAL, points.data(), nullptr), RMF_OK, "");
    CHECK_STATUS(rmf_sheet_part_surface_to_flat(part, points.data(), points.size(), RMF_SHEET_LAYER_NEUTRAL, 1e-9 * size, back.data()), RMF_OK, "");
    double round_trip = 0, on_surface = 0, geodesic = 0;
    for (size_t k = 0; k < flat.size(); ++k) round_trip = std::max(round_trip, std::hypot(back[k].x - flat[k].x, back[k].y - flat[k].y) / size);
    for (size_t k = 0; k < flat.size(); k += 25) on_surface = std::max(on_surface, surface_distance(neutral, points[k]) / size);
    for (size_t k = 0; k < flat.size(); k += 10) {
        /* A flat segment of length 1 (if inside) and the polyline of its image, 64 and 128
         * chords, Richardson-extrapolated. */
        const double a = 6.283185307179586 * random();
        const RmfVec2 q{flat[k].x + std::cos(a), flat[k].y + std::sin(a)};
        double margin;
        if (!inside(poly, q.x, q.y, &margin)) continue;
        double lengths[2];
        for (int level = 0; level < 2; ++level) {
            const int m = 64 << level;
            std::vector<RmfVec2> seg(m + 1);
            std::vector<RmfVec3> img(m + 1);
            for (int j = 0; j <= m; ++j) seg[j] = RmfVec2{flat[k].x + (q.x - flat[k].x) * j / m, flat[k].y + (q.y - flat[k].y) * j / m};
            CHECK_STATUS(rmf_sheet_part_flat_to_surface(part, seg.data(), seg.size(), RMF_SHEET_LAYER_NEUTRAL, img.data(), nullptr), RMF_OK, "");
            lengths[level] = 0;
            for (int j = 0; j < m; ++j) lengths[level] += ne_dist(img[j], img[j + 1]);
        }
        geodesic = std::max(geodesic, std::fabs((4 * lengths[1] - lengths[0]) / 3 - 1));
    }
    std::printf("  round trip max %.3e (relative to the pattern's size %.1f); 40 points on the neutral NURBS within "
                "%.3e; flat segments of length 1 against their images: max %.3e\n",
                round_trip, size, on_surface, geodesic);
    CHECK(round_trip <= 1e-12, "round trip to 1e-12 relative");
    CHECK(on_surface <= 1e-12, "mapped points lie on the neutral layer");
    CHECK(geodesic <= 1e-8, "distances kept (isometry)");
    rmf_surface_free(s_designed);
    rmf_surface_free(s_neutral);
    rmf_sheet_part_free(part);

    std::printf("E. pieces per tolerance\n");
    size_t previous = 0;
    for (double tol : {1e-2, 1e-3, 1e-4, 1e-5}) {
        RmfSheetPart *p = hopper(tol);
        if (!p) continue;
        rmf_sheet_part_report(p, &report);
        const double b = edge_distance(p, RMF_SHEET_SIDE_FIRST, square_distance), t = edge_distance(p, RMF_SHEET_SIDE_SECOND, circle_distance);
        std::printf("  tolerance %.0e: %4zu pieces, surface deviation %.3e, edges %.3e / %.3e\n", tol, report.pieces,
                    report.deviation, b, t);
        CHECK(b <= tol && t <= tol && report.deviation <= tol, "within the tolerance");
        CHECK(report.pieces > previous, "more pieces for a smaller tolerance");
        previous = report.pieces;
        rmf_sheet_part_free(p);
    }
    return rmf_check_exit_code("geometry_sheet");
}
