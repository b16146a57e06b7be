/*
 * The boundary representation through the C API (RmfBrep: rmf_shape_brep,
 * rmf_sheet_part_brep and the rmf_brep_* accessors), checked with the suite's own
 * arithmetic: every edge of a solid used once each way once the faces' senses are applied
 * (a degenerate edge once, at one vertex), loops that run on from vertex to vertex, edge
 * curves that end at their vertices, and every edge's curve on each face — evaluated on
 * the face's surface by the suite's own NURBS evaluator — on the edge's 3-D curve. Shells
 * cover the faces once. On a pipe route with a ring (holes), its open walls (two shells),
 * the ring round a closed loop (a solid of two shells: the cavity's wall) and the
 * square-to-round hopper (degenerate edges). Bad input names the argument.
 *
 * The analytic forms (rmf_brep_face_analytic, rmf_brep_edge_analytic,
 * rmf_brep_analytic_use), with the suite's own formulas for OpenCascade's cylinder,
 * torus, line and circle: every analytic face holds its NURBS surface's points, every
 * analytic edge runs from its start vertex through its NURBS curve's points to its end
 * vertex, and every use's line on an analytic face maps to its edge's analytic curve.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "nurbs_eval.h"
#include "rmf_check.h"

static RmfEdge line(RmfVec3 a, RmfVec3 b) {
    RmfEdge e = {RMF_EDGE_LINE, {a, b, {0, 0, 0}}, NULL};
    return e;
}

static RmfEdge arc(RmfVec3 a, RmfVec3 m, RmfVec3 b) {
    RmfEdge e = {RMF_EDGE_ARC, {a, m, b}, NULL};
    return e;
}

/* Line, quarter arc, line, quarter arc, line. */
static void pipe_route(RmfEdge e[5]) {
    const double s = sqrt(0.5);
    e[0] = line(vec3(0, 0, 0), vec3(10, 0, 0));
    e[1] = arc(vec3(10, 0, 0), vec3(10 + 3 * s, 3 - 3 * s, 0), vec3(13, 3, 0));
    e[2] = line(vec3(13, 3, 0), vec3(13, 12, 0));
    e[3] = arc(vec3(13, 12, 0), vec3(13, 12 + 3 * s, 3 - 3 * s), vec3(13, 15, 3));
    e[4] = line(vec3(13, 15, 3), vec3(13, 15, 12));
}

/* The point of a use's curve in its face's parameter plane at the edge parameter t. */
static void pcurve_at(const RmfBrepUse *u, double t, double *x, double *y) {
    if (u->pcurve_kind == RMF_PCURVE_LINE) {
        *x = u->line_origin.x + t * u->line_direction.x;
        *y = u->line_origin.y + t * u->line_direction.y;
    } else {
        RmfVec3 d[3];
        ne_curve_derivatives(&u->pcurve, t, d);
        *x = d[0].x;
        *y = d[0].y;
    }
}

static RmfVec3 add(RmfVec3 a, RmfVec3 b, double k) { return vec3(a.x + k * b.x, a.y + k * b.y, a.z + k * b.z); }

static RmfVec3 cross(RmfVec3 a, RmfVec3 b) {
    return vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

/* A point of an analytic surface (cylinder, torus) or curve (line, circle). */
static RmfVec3 analytic_at(const RmfBrepAnalytic *a, double u, double v) {
    RmfVec3 y = cross(a->axis, a->x_axis);
    RmfVec3 radial = add(vec3(0, 0, 0), a->x_axis, cos(u));
    radial = add(radial, y, sin(u));
    switch (a->kind) {
    case RMF_ANALYTIC_CYLINDER: return add(add(a->location, radial, a->radius), a->axis, v);
    case RMF_ANALYTIC_TORUS:
        return add(add(a->location, radial, a->radius + a->minor_radius * cos(v)), a->axis, a->minor_radius * sin(v));
    case RMF_ANALYTIC_LINE: return add(a->location, a->axis, u);
    case RMF_ANALYTIC_CIRCLE: return add(a->location, radial, a->radius);
    default: return vec3(NAN, NAN, NAN);
    }
}

/* The distance of p from an analytic cylinder or torus. */
static double off_surface(const RmfBrepAnalytic *a, RmfVec3 p) {
    RmfVec3 d = add(p, a->location, -1);
    double h = ne_dot(d, a->axis);
    double across = ne_norm(add(d, a->axis, -h));
    if (a->kind == RMF_ANALYTIC_CYLINDER) return fabs(across - a->radius);
    return fabs(hypot(across - a->radius, h) - a->minor_radius);
}

/* The analytic forms of a B-rep against its NURBS views; the cylinders and tori counted. */
static void check_analytic(const RmfBrep *brep, const char *what, double size, size_t cylinders, size_t tori) {
    RmfBrepCounts counts;
    RmfBrepAnalytic a, edge;
    RmfBrepFace face;
    RmfBrepLoop lp;
    RmfBrepUse u;
    size_t f, l, k, i, j, count[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    double worst_surface = 0, worst_use = 0, worst_vertex = 0;
    CHECK_STATUS(rmf_brep_counts(brep, &counts), RMF_OK, "");
    for (k = 0; k < counts.edge_count; ++k) {
        RmfBrepEdge e;
        RmfVec3 a0, a1;
        rmf_brep_edge(brep, k, &e);
        CHECK_STATUS(rmf_brep_edge_analytic(brep, k, &edge), RMF_OK, "");
        if (edge.kind == RMF_ANALYTIC_NONE) continue;
        rmf_brep_vertex(brep, e.start, &a0);
        rmf_brep_vertex(brep, e.end, &a1);
        worst_vertex = fmax(worst_vertex, ne_dist(analytic_at(&edge, 0, 0), a0));
        worst_vertex = fmax(worst_vertex, ne_dist(analytic_at(&edge, edge.end, 0), a1));
    }
    for (f = 0; f < counts.face_count; ++f) {
        CHECK_STATUS(rmf_brep_face_analytic(brep, f, &a), RMF_OK, "");
        rmf_brep_face(brep, f, &face);
        if (a.kind == RMF_ANALYTIC_NONE || a.kind == RMF_ANALYTIC_PLANE) {
            if (a.kind == RMF_ANALYTIC_NONE)
                CHECK_STATUS(rmf_brep_analytic_use(brep, f, 0, 0, &u), RMF_ERROR_INVALID_INPUT, "face");
            continue;
        }
        count[a.kind & 7]++;
        if (a.kind != RMF_ANALYTIC_CYLINDER && a.kind != RMF_ANALYTIC_TORUS) continue;
        for (i = 0; i <= 4; ++i) {
            for (j = 0; j <= 4; ++j) {
                const RmfNurbsSurface *s = &face.nurbs;
                RmfVec3 d[3][3];
                double u0 = s->knots_u[0], u1 = s->knots_u[s->knot_count_u - 1];
                double v0 = s->knots_v[0], v1 = s->knots_v[s->knot_count_v - 1];
                ne_surface_derivatives(s, u0 + (u1 - u0) * i / 4.0, v0 + (v1 - v0) * j / 4.0, d);
                worst_surface = fmax(worst_surface, off_surface(&a, d[0][0]));
            }
        }
        for (l = 0; l < face.loop_count; ++l) {
            rmf_brep_loop(brep, f, l, &lp);
            for (k = 0; k < lp.use_count; ++k) {
                CHECK_STATUS(rmf_brep_analytic_use(brep, f, l, k, &u), RMF_OK, "");
                CHECK_STATUS(rmf_brep_edge_analytic(brep, u.edge, &edge), RMF_OK, "");
                CHECK(edge.kind == RMF_ANALYTIC_LINE || edge.kind == RMF_ANALYTIC_CIRCLE,
                      "an analytic face uses analytic edges");
                CHECK(u.pcurve_kind == RMF_PCURVE_LINE, "a line on the analytic surface");
                for (i = 0; i <= 4; ++i) {
                    double t = edge.end * i / 4.0;
                    double x = u.line_origin.x + t * u.line_direction.x;
                    double y = u.line_origin.y + t * u.line_direction.y;
                    worst_use = fmax(worst_use, ne_dist(analytic_at(&a, x, y), analytic_at(&edge, t, 0)));
                }
            }
        }
    }
    printf("%s: %zu cylinders, %zu tori; surfaces %.1e, uses %.1e, vertices %.1e off\n", what, count[2], count[3],
           worst_surface, worst_use, worst_vertex);
    CHECK(count[RMF_ANALYTIC_CYLINDER] == cylinders && count[RMF_ANALYTIC_TORUS] == tori, "the analytic faces");
    CHECK(worst_surface <= 1e-12 * size && worst_use <= 1e-12 * size && worst_vertex <= 1e-12 * size,
          "the analytic forms are the NURBS geometry");
    CHECK_STATUS(rmf_brep_face_analytic(brep, counts.face_count, &a), RMF_ERROR_INVALID_INPUT, "index");
    CHECK_STATUS(rmf_brep_edge_analytic(brep, counts.edge_count, &a), RMF_ERROR_INVALID_INPUT, "index");
    CHECK_STATUS(rmf_brep_edge_analytic(brep, 0, NULL), RMF_ERROR_NULL_POINTER, "out");
    CHECK_STATUS(rmf_brep_face_analytic(NULL, 0, &a), RMF_ERROR_NULL_POINTER, "brep");
}

/* The checks of the file's header on one B-rep; `size` scales the distances. */
static void check_model(const RmfBrep *brep, const char *what, size_t shells_expected, double size) {
    RmfBrepCounts counts;
    size_t f, l, k, e, s, uses_total = 0;
    int *forward, *backward, *in_shell;
    double worst_end = 0, worst_pcurve = 0;
    CHECK_STATUS(rmf_brep_counts(brep, &counts), RMF_OK, "");
    printf("%s: %zu vertices, %zu edges, %zu faces, %zu shell(s), solid %u, tolerance %.1e\n", what,
           counts.vertex_count, counts.edge_count, counts.face_count, counts.shell_count, counts.solid,
           counts.tolerance);
    CHECK(counts.shell_count == shells_expected, what);
    forward = calloc(counts.edge_count, sizeof *forward);
    backward = calloc(counts.edge_count, sizeof *backward);
    in_shell = calloc(counts.face_count, sizeof *in_shell);
    if (!forward || !backward || !in_shell) {
        CHECK(0, "memory");
        free(forward), free(backward), free(in_shell);
        return;
    }
    for (f = 0; f < counts.face_count; ++f) {
        RmfBrepFace face;
        CHECK_STATUS(rmf_brep_face(brep, f, &face), RMF_OK, "");
        CHECK(face.loop_count >= 1, "a face has a loop");
        for (l = 0; l < face.loop_count; ++l) {
            RmfBrepLoop bound;
            size_t previous_end = SIZE_MAX, first_start = SIZE_MAX;
            CHECK_STATUS(rmf_brep_loop(brep, f, l, &bound), RMF_OK, "");
            CHECK(bound.outer == (l == 0), "the outer loop first");
            for (k = 0; k < bound.use_count; ++k) {
                RmfBrepUse u;
                RmfBrepEdge edge;
                size_t from, to;
                CHECK_STATUS(rmf_brep_use(brep, f, l, k, &u), RMF_OK, "");
                CHECK_STATUS(rmf_brep_edge(brep, u.edge, &edge), RMF_OK, "");
                from = u.forward ? edge.start : edge.end;
                to = u.forward ? edge.end : edge.start;
                if (k == 0) first_start = from;
                else CHECK(from == previous_end, "consecutive uses meet at a vertex");
                previous_end = to;
                if ((u.forward != 0) == (face.same_sense != 0)) forward[u.edge]++;
                else backward[u.edge]++;
                uses_total++;
                if (face.kind == RMF_BREP_SURFACE_NURBS) {
                    int j;
                    CHECK(u.pcurve_kind != RMF_PCURVE_NONE, "every edge has its curve on a B-spline face");
                    for (j = 0; j <= 4; ++j) {
                        const double a = edge.curve.knots[0], b = edge.curve.knots[edge.curve.knot_count - 1];
                        const double t = a + (b - a) * j / 4.0;
                        RmfVec3 c[3], d[3][3];
                        double x, y;
                        ne_curve_derivatives(&edge.curve, t, c);
                        pcurve_at(&u, t, &x, &y);
                        ne_surface_derivatives(&face.nurbs, x, y, d);
                        if (ne_dist(c[0], d[0][0]) > worst_pcurve) worst_pcurve = ne_dist(c[0], d[0][0]);
                    }
                }
            }
            CHECK(bound.use_count == 0 || previous_end == first_start, "a loop closes");
        }
    }
    for (e = 0; e < counts.edge_count; ++e) {
        RmfBrepEdge edge;
        RmfVec3 start, end, c[3];
        CHECK_STATUS(rmf_brep_edge(brep, e, &edge), RMF_OK, "");
        CHECK_STATUS(rmf_brep_vertex(brep, edge.start, &start), RMF_OK, "");
        CHECK_STATUS(rmf_brep_vertex(brep, edge.end, &end), RMF_OK, "");
        ne_curve_derivatives(&edge.curve, edge.curve.knots[0], c);
        if (ne_dist(c[0], start) > worst_end) worst_end = ne_dist(c[0], start);
        ne_curve_derivatives(&edge.curve, edge.curve.knots[edge.curve.knot_count - 1], c);
        if (ne_dist(c[0], end) > worst_end) worst_end = ne_dist(c[0], end);
        if (edge.degenerate) {
            CHECK(edge.start == edge.end && forward[e] + backward[e] == 1, "a degenerate edge: one vertex, one use");
        } else if (counts.solid) {
            CHECK(forward[e] == 1 && backward[e] == 1, "a solid's edge is used once each way");
        } else {
            CHECK(forward[e] <= 1 && backward[e] <= 1 && forward[e] + backward[e] >= 1,
                  "a sheet's edge is used at most once each way");
        }
    }
    for (s = 0; s < counts.shell_count; ++s) {
        RmfBrepShell shell;
        CHECK_STATUS(rmf_brep_shell(brep, s, &shell), RMF_OK, "");
        for (k = 0; k < shell.face_count; ++k)
            if (shell.faces[k] < counts.face_count) in_shell[shell.faces[k]]++;
    }
    for (f = 0; f < counts.face_count; ++f) CHECK(in_shell[f] == 1, "every face in one shell");
    printf("  %zu edge uses; edge curves from their vertices %.1e, pcurves on the faces from the edges %.1e "
           "(own evaluator)\n",
           uses_total, worst_end, worst_pcurve);
    CHECK(worst_end <= 1e-12 * size, "edge curves end at their vertices");
    CHECK(worst_pcurve <= 1e-9 * size, "each edge's curve on a face is the edge");
    /* Bad input names the argument and writes nothing. */
    {
        RmfBrepEdge edge;
        RmfBrepUse u;
        RmfVec3 p = vec3(7, 7, 7);
        CHECK_STATUS(rmf_brep_counts(NULL, &counts), RMF_ERROR_NULL_POINTER, "brep");
        CHECK_STATUS(rmf_brep_counts(brep, NULL), RMF_ERROR_NULL_POINTER, "out");
        CHECK_STATUS(rmf_brep_vertex(brep, counts.vertex_count, &p), RMF_ERROR_INVALID_INPUT, "index");
        CHECK(p.x == 7, "a failing call writes nothing");
        CHECK_STATUS(rmf_brep_edge(brep, counts.edge_count, &edge), RMF_ERROR_INVALID_INPUT, "index");
        CHECK_STATUS(rmf_brep_use(brep, counts.face_count, 0, 0, &u), RMF_ERROR_INVALID_INPUT, "face");
        CHECK_STATUS(rmf_brep_use(brep, 0, 99, 0, &u), RMF_ERROR_INVALID_INPUT, "loop");
        CHECK_STATUS(rmf_brep_use(brep, 0, 0, 999999, &u), RMF_ERROR_INVALID_INPUT, "index");
        CHECK_STATUS(rmf_brep_shell(brep, counts.shell_count, NULL), RMF_ERROR_NULL_POINTER, "out");
    }
    free(forward), free(backward), free(in_shell);
}

static void test_pipe(void) {
    RmfEdge e[5];
    RmfCurve *ring = NULL, *hole = NULL;
    RmfShape *solid = NULL, *walls = NULL;
    RmfBrep *brep = NULL;
    RmfWireSweepOptions o;
    pipe_route(e);
    CHECK_STATUS(rmf_curve_circle(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), 1.0, &ring), RMF_OK, "");
    CHECK_STATUS(rmf_curve_circle(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), 0.5, &hole), RMF_OK, "");
    CHECK_STATUS(rmf_wire_sweep(e, 5, ring, (const RmfCurve *const *)&hole, 1, NULL, &solid), RMF_OK, "");
    CHECK_STATUS(rmf_shape_brep(solid, &brep), RMF_OK, "");
    if (brep) check_model(brep, "pipe route with a ring, solid", 1, 20);
    /* 3 lines and 2 arcs, each circle's 4 quarters joined: 6 cylinders, 4 tori. */
    if (brep) check_analytic(brep, "pipe route with a ring, solid", 20, 6, 4);
    rmf_brep_free(brep);
    brep = NULL;
    rmf_wire_sweep_options_init(&o);
    o.solid = 0;
    CHECK_STATUS(rmf_wire_sweep(e, 5, ring, (const RmfCurve *const *)&hole, 1, &o, &walls), RMF_OK, "");
    CHECK_STATUS(rmf_shape_brep(walls, &brep), RMF_OK, "");
    if (brep) check_model(brep, "pipe route with a ring, open walls", 2, 20);
    rmf_brep_free(brep);
    brep = NULL;
    {
        /* Round a closed square loop: a solid with a cavity, two closed shells. */
        RmfEdge loop[4];
        RmfShape *hollow = NULL;
        loop[0] = line(vec3(0, 0, 0), vec3(20, 0, 0));
        loop[1] = line(vec3(20, 0, 0), vec3(20, 20, 0));
        loop[2] = line(vec3(20, 20, 0), vec3(0, 20, 0));
        loop[3] = line(vec3(0, 20, 0), vec3(0, 0, 0));
        CHECK_STATUS(rmf_wire_sweep(loop, 4, ring, (const RmfCurve *const *)&hole, 1, NULL, &hollow), RMF_OK, "");
        CHECK_STATUS(rmf_shape_brep(hollow, &brep), RMF_OK, "");
        if (brep) check_model(brep, "ring round a closed loop, a solid with a cavity", 2, 30);
        rmf_brep_free(brep);
        rmf_shape_free(hollow);
    }
    brep = (RmfBrep *)(uintptr_t)0x5e5e;
    CHECK_STATUS(rmf_shape_brep(NULL, &brep), RMF_ERROR_NULL_POINTER, "shape");
    CHECK(brep == (RmfBrep *)(uintptr_t)0x5e5e, "a failing call writes no out-pointer");
    CHECK_STATUS(rmf_shape_brep(solid, NULL), RMF_ERROR_NULL_POINTER, "out");
    rmf_brep_free(NULL);
    rmf_shape_free(solid);
    rmf_shape_free(walls);
    rmf_curve_free(ring);
    rmf_curve_free(hole);
}

static void test_hopper(void) {
    const RmfVec3 corners[4] = {{-100, -100, 0}, {100, -100, 0}, {100, 100, 0}, {-100, 100, 0}};
    RmfCurve *square = NULL, *circle = NULL;
    RmfSheetPart *part = NULL;
    RmfBrep *brep = NULL;
    RmfSheetOptions o;
    CHECK_STATUS(rmf_curve_polygon(corners, 4, &square), RMF_OK, "");
    CHECK_STATUS(rmf_curve_circle(vec3(20, 0, 150), vec3(1, 0, 0), vec3(0, 1, 0), 60, &circle), RMF_OK, "");
    rmf_sheet_options_init(&o);
    o.thickness = 2;
    o.tolerance = 1e-3;
    CHECK_STATUS(rmf_sheet_part_transition(square, circle, &o, &part), RMF_OK, "");
    CHECK_STATUS(rmf_sheet_part_brep(part, &brep), RMF_OK, "");
    if (brep) {
        RmfBrepCounts counts;
        size_t e, degenerate = 0;
        check_model(brep, "square-to-round hopper", 1, 200);
        rmf_brep_counts(brep, &counts);
        for (e = 0; e < counts.edge_count; ++e) {
            RmfBrepEdge edge;
            rmf_brep_edge(brep, e, &edge);
            degenerate += edge.degenerate;
        }
        CHECK(counts.solid == 1 && degenerate >= 8, "the hopper: a solid with degenerate edges at the apices");
    }
    rmf_brep_free(brep);
    brep = NULL;
    CHECK_STATUS(rmf_sheet_part_brep(NULL, &brep), RMF_ERROR_NULL_POINTER, "part");
    CHECK_STATUS(rmf_sheet_part_brep(part, NULL), RMF_ERROR_NULL_POINTER, "out");
    CHECK(brep == NULL, "nothing written");
    rmf_sheet_part_free(part);
    rmf_curve_free(square);
    rmf_curve_free(circle);
}

int main(void) {
    test_pipe();
    test_hopper();
    return rmf_check_exit_code("abi_brep");
}
