/*
 * rmfsurf demo: builds objects through the C API and writes files you can open in
 * ParaView (.vtp) or any mesh viewer (.obj).
 *
 *   demo [output-directory]     (default: rmfsurf-demo)
 *
 * Sections:
 *   1. a NURBS input curve, its double-reflection rotation-minimizing frames and its Frenet
 *      frames (polyline with frame vectors, and a ribbon along f2 for each frame);
 *   2. a rational NURBS surface given as input, tessellated by the library;
 *   3. RRMF quintics (Farouki, Giannelli & Sestini): the Hermite interpolants of Example 1,
 *      the helix spline of Example 3 with its exact rational RMF, and a developable strip
 *      and a pipe swept along it;
 *   4. a cone spline approximating the tangent surface of a twisted cubic (.obj/.vtp), and
 *      its exact development as SVG with true circular arcs;
 *   5. profile surfaces along PH cubic splines: a moulding along a conical helix with the
 *      rational RMF and with the Frenet frame, and a square tube along a closed trefoil;
 *   6. a curve with an exact rational RMF by Möbius transformations of planar PH cubics
 *      (Bartoň, Jüttler & Wang), and the developable strip x + v f2 swept along it;
 *   7. wire sweeps: a pipe route of lines, a tangent arc and a NURBS edge swept as a hollow
 *      pipe, and a square duct along a polyline with mitred corners: closed solids written
 *      as STEP (open them in FreeCAD), one face of each as a mesh.
 *   8. sheet metal: a square-to-round hopper (square 200 × 200, circle of radius 60 150 above,
 *      offset by 20) of 2 mm sheet, K-factor 0.4 — the formed solid as STEP, the flat pattern
 *      of its neutral layer for the cutter as DXF (lines and arcs, bend lines on their own
 *      layer) and SVG, and a hole marked in the flat pattern carried onto the formed part.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "rmfsurf.h"

#define SAMPLES 241

static const char *out_dir = "rmfsurf-demo";

static void fail(const char *what, RmfStatus status) {
    fprintf(stderr, "demo: %s failed: %s: %s\n", what, rmf_status_name(status), rmf_last_error());
    exit(1);
}

#define TRY(call)                            \
    do {                                     \
        RmfStatus demo_status_ = (call);     \
        if (demo_status_ != RMF_OK) fail(#call, demo_status_); \
    } while (0)

static FILE *open_output(const char *name, char *path, size_t size) {
    FILE *f;
    snprintf(path, size, "%s/%s", out_dir, name);
    f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "demo: cannot write %s: %s\n", path, strerror(errno));
        exit(1);
    }
    return f;
}

static void written(const char *path, const char *what) { printf("  wrote %-40s %s\n", path, what); }

/* ---- file writers (VTK XML PolyData, ASCII; Wavefront OBJ) ---- */

static void vtp_points(FILE *f, const RmfVec3 *p, size_t n) {
    size_t i;
    fprintf(f, "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for (i = 0; i < n; i++) fprintf(f, "          %.17g %.17g %.17g\n", p[i].x, p[i].y, p[i].z);
    fprintf(f, "        </DataArray>\n      </Points>\n");
}

static void vtp_vectors(FILE *f, const char *name, const RmfVec3 *v, size_t n) {
    size_t i;
    fprintf(f, "        <DataArray type=\"Float64\" Name=\"%s\" NumberOfComponents=\"3\" format=\"ascii\">\n", name);
    for (i = 0; i < n; i++) fprintf(f, "          %.17g %.17g %.17g\n", v[i].x, v[i].y, v[i].z);
    fprintf(f, "        </DataArray>\n");
}

/* A polyline through the points, with named vector arrays at the points. */
static void write_polyline_vtp(const char *name, const RmfVec3 *p, size_t n, const char **names,
                               const RmfVec3 **vectors, size_t vector_count, const char *what) {
    char path[1024];
    FILE *f = open_output(name, path, sizeof path);
    size_t i;
    fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n");
    fprintf(f, "  <PolyData>\n    <Piece NumberOfPoints=\"%zu\" NumberOfLines=\"1\">\n", n);
    vtp_points(f, p, n);
    fprintf(f, "      <PointData Vectors=\"%s\">\n", vector_count ? names[0] : "");
    for (i = 0; i < vector_count; i++) vtp_vectors(f, names[i], vectors[i], n);
    fprintf(f, "      </PointData>\n      <Lines>\n");
    fprintf(f, "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n         ");
    for (i = 0; i < n; i++) fprintf(f, " %zu", i);
    fprintf(f, "\n        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\"> %zu </DataArray>\n", n);
    fprintf(f, "      </Lines>\n    </Piece>\n  </PolyData>\n</VTKFile>\n");
    fclose(f);
    written(path, what);
}

static void write_mesh_vtp(const char *name, const RmfVec3 *p, size_t n, const uint32_t *tri, size_t nt,
                           const char *what) {
    char path[1024];
    FILE *f = open_output(name, path, sizeof path);
    size_t i;
    fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n");
    fprintf(f, "  <PolyData>\n    <Piece NumberOfPoints=\"%zu\" NumberOfPolys=\"%zu\">\n", n, nt);
    vtp_points(f, p, n);
    fprintf(f, "      <Polys>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    for (i = 0; i < nt; i++) fprintf(f, "          %u %u %u\n", tri[3 * i], tri[3 * i + 1], tri[3 * i + 2]);
    fprintf(f, "        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for (i = 0; i < nt; i++) fprintf(f, "          %zu\n", 3 * (i + 1));
    fprintf(f, "        </DataArray>\n      </Polys>\n    </Piece>\n  </PolyData>\n</VTKFile>\n");
    fclose(f);
    written(path, what);
}

static void write_mesh_obj(const char *name, const RmfVec3 *p, size_t n, const uint32_t *tri, size_t nt,
                           const char *what) {
    char path[1024];
    FILE *f = open_output(name, path, sizeof path);
    size_t i;
    fprintf(f, "# rmfsurf demo: %s\n", what);
    for (i = 0; i < n; i++) fprintf(f, "v %.17g %.17g %.17g\n", p[i].x, p[i].y, p[i].z);
    for (i = 0; i < nt; i++) fprintf(f, "f %u %u %u\n", tri[3 * i] + 1, tri[3 * i + 1] + 1, tri[3 * i + 2] + 1);
    fclose(f);
    written(path, what);
}

/* A strip x(t) + s w f2(t), s ∈ [−1, 1], over the samples: shows how a frame turns. */
static void write_ribbon(const char *name, const RmfVec3 *x, const RmfVec3 *f2, size_t n, double w, const char *what) {
    RmfVec3 *p = (RmfVec3 *)malloc(2 * n * sizeof *p);
    uint32_t *tri = (uint32_t *)malloc(6 * (n - 1) * sizeof *tri);
    size_t i;
    if (!p || !tri) exit(1);
    for (i = 0; i < n; i++) {
        p[2 * i].x = x[i].x - w * f2[i].x;
        p[2 * i].y = x[i].y - w * f2[i].y;
        p[2 * i].z = x[i].z - w * f2[i].z;
        p[2 * i + 1].x = x[i].x + w * f2[i].x;
        p[2 * i + 1].y = x[i].y + w * f2[i].y;
        p[2 * i + 1].z = x[i].z + w * f2[i].z;
    }
    for (i = 0; i + 1 < n; i++) {
        uint32_t a = (uint32_t)(2 * i), b = a + 1, c = a + 2, d = a + 3;
        uint32_t *t = tri + 6 * i;
        t[0] = a, t[1] = c, t[2] = d, t[3] = a, t[4] = d, t[5] = b;
    }
    write_mesh_obj(name, p, 2 * n, tri, 2 * (n - 1), what);
    free(p);
    free(tri);
}

/* The surface tessellated by the library, written as <name>.obj and <name>.vtp. */
static void write_tessellation(const RmfSurface *surface, uint32_t u_steps, uint32_t v_steps, const char *name,
                               const char *what) {
    RmfVec3 *points;
    uint32_t *triangles;
    size_t np, nt;
    char obj[256], vtp[256];
    TRY(rmf_surface_tessellate(surface, u_steps, v_steps, NULL, 0, NULL, 0, &np, &nt));
    points = (RmfVec3 *)malloc(np * sizeof *points);
    triangles = (uint32_t *)malloc(3 * nt * sizeof *triangles);
    if (!points || !triangles) exit(1);
    TRY(rmf_surface_tessellate(surface, u_steps, v_steps, points, np, triangles, nt, &np, &nt));
    snprintf(obj, sizeof obj, "%s.obj", name);
    snprintf(vtp, sizeof vtp, "%s.vtp", name);
    write_mesh_obj(obj, points, np, triangles, nt, what);
    write_mesh_vtp(vtp, points, np, triangles, nt, "the same mesh as VTK PolyData");
    free(points);
    free(triangles);
}

/* ---- 1. a NURBS curve with its rotation-minimizing and Frenet frames ---- */

static void demo_curve_and_frames(void) {
    /* A cubic B-spline climbing around the z axis: 8 poles, 5 Bézier segments. */
    static const RmfVec3 poles[8] = {{2, 0, 0},  {2, 2, 0.5}, {-1, 3, 1},  {-3, 0, 1.5},
                                     {-1, -3, 2}, {2, -2, 2.5}, {3, 1, 3}, {1, 2, 3.5}};
    static const double knots[12] = {0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5};
    static RmfVec3 x[SAMPLES], t[SAMPLES], rmf2[SAMPLES], rmf3[SAMPLES], fr2[SAMPLES], fr3[SAMPLES];
    const char *names[5] = {"tangent", "rmf_f2", "rmf_f3", "frenet_n", "frenet_b"};
    const RmfVec3 *vectors[5];
    RmfCurve *curve = NULL;
    RmfFrames *rmf = NULL, *frenet = NULL;
    RmfVec3 seed = {0, 0, 1};
    double t0, t1, twist_rmf = 0, twist_frenet = 0;
    size_t i;

    printf("1. NURBS curve, double-reflection RMF and Frenet frames\n");
    TRY(rmf_nurbs_curve_create(3, poles, NULL, 8, knots, 12, &curve));
    TRY(rmf_curve_domain(curve, &t0, &t1));
    TRY(rmf_double_reflection_frames(curve, seed, 2000, &rmf));
    TRY(rmf_frenet_frames(curve, &frenet));
    for (i = 0; i < SAMPLES; i++) {
        double s = t0 + (t1 - t0) * (double)i / (SAMPLES - 1);
        RmfVec3 dummy;
        TRY(rmf_curve_eval(curve, s, &x[i], NULL));
        TRY(rmf_frames_eval(rmf, s, &t[i], &rmf2[i], &rmf3[i]));
        TRY(rmf_frames_eval(frenet, s, &dummy, &fr2[i], &fr3[i]));
        if (i > 0) {
            /* Rotation about the tangent between consecutive samples. */
            twist_rmf += fabs(asin(fmin(1.0, fabs(rmf2[i - 1].x * rmf3[i].x + rmf2[i - 1].y * rmf3[i].y +
                                                   rmf2[i - 1].z * rmf3[i].z))));
            twist_frenet += fabs(asin(fmin(1.0, fabs(fr2[i - 1].x * fr3[i].x + fr2[i - 1].y * fr3[i].y +
                                                      fr2[i - 1].z * fr3[i].z))));
        }
    }
    vectors[0] = t, vectors[1] = rmf2, vectors[2] = rmf3, vectors[3] = fr2, vectors[4] = fr3;
    write_polyline_vtp("curve_frames.vtp", x, SAMPLES, names, vectors, 5,
                       "NURBS curve with RMF and Frenet frame vectors");
    write_ribbon("rmf_ribbon.obj", x, rmf2, SAMPLES, 0.4, "strip along the RMF vector f2 (no twist)");
    write_ribbon("frenet_ribbon.obj", x, fr2, SAMPLES, 0.4, "strip along the Frenet normal (twists)");
    printf("  summed rotation about the tangent between samples: RMF %.4f rad, Frenet %.4f rad\n", twist_rmf,
           twist_frenet);
    rmf_frames_free(rmf);
    rmf_frames_free(frenet);
    rmf_curve_free(curve);
}

/* ---- 2. a rational NURBS surface, tessellated ---- */

static void demo_tessellated_surface(void) {
    /* A quarter torus-like rational patch: circle of radius 0.5 swept around a circle of radius 2. */
    const double s = sqrt(0.5);
    const double ring[3][3] = {{1, 0, 1}, {1, 1, s}, {0, 1, 1}};
    const double knots[6] = {0, 0, 0, 1, 1, 1};
    RmfVec3 poles[9];
    double weights[9];
    RmfNurbsSurfaceData data = {0};
    RmfSurface *surface = NULL;
    int i, j;

    printf("2. rational NURBS surface (a quarter of a torus), tessellated by the library\n");
    for (i = 0; i < 3; i++)     /* u: around the tube */
        for (j = 0; j < 3; j++) { /* v: around the axis */
            double r = 2.0 + 0.5 * ring[i][0], z = 0.5 * ring[i][1];
            double wij = ring[i][2] * ring[j][2];
            poles[i * 3 + j].x = r * ring[j][0];
            poles[i * 3 + j].y = r * ring[j][1];
            poles[i * 3 + j].z = z;
            weights[i * 3 + j] = wij;
        }
    /* Middle poles of the tube circle sit on the tangent lines: r = 2 + 0.5, z = 0.5. */
    data.struct_size = sizeof data;
    data.degree_u = data.degree_v = 2;
    data.pole_count_u = data.pole_count_v = 3;
    data.poles = poles;
    data.weights = weights;
    data.knot_count_u = data.knot_count_v = 6;
    data.knots_u = data.knots_v = knots;
    TRY(rmf_nurbs_surface_create_from(&data, &surface));
    write_tessellation(surface, 24, 24, "torus_patch", "tessellated rational NURBS surface");
    rmf_surface_free(surface);
}

/* ---- 3. RRMF quintics: Hermite interpolants, a spline with its exact rational RMF, sweeps ---- */

static void demo_rrmf_quintics(void) {
    /* Example 1 of Farouki, Giannelli & Sestini, and the helix data of their Example 3. */
    const RmfVec3 p0 = {0, 0, 0}, t0 = {1, 0, 1}, p1 = {1, 1, 1}, t1 = {0, 1, 1}, up = {0, 0, 1};
    static const RmfVec3 line_poles[2] = {{0.15, -0.25, 0}, {0.15, 0.25, 0}};
    static const double line_knots[4] = {0, 0, 1, 1};
    static const double ring[9][3] = {{1, 0, 1}, {1, 1, 0}, {0, 1, 1}, {-1, 1, 0}, {-1, 0, 1},
                                      {-1, -1, 0}, {0, -1, 1}, {1, -1, 0}, {1, 0, 1}};
    static const double circle_knots[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    static RmfVec3 x[SAMPLES], t[SAMPLES], f2[SAMPLES], f3[SAMPLES];
    const char *names[3] = {"tangent", "rmf_f2", "rmf_f3"};
    const RmfVec3 *vectors[3];
    RmfVec3 points[10], tangents[10], circle_poles[9];
    double circle_weights[9], t_min, t_max, joint_gap = 0;
    RmfRrmfQuintic solutions[4], best;
    RmfCurve *spline = NULL, *line = NULL, *circle = NULL;
    RmfFrames *frames = NULL;
    RmfSurface *strip = NULL, *tube = NULL;
    size_t n = 0, admissible = 0, i;
    int k;

    printf("3. RRMF quintics (rational rotation-minimizing frames of degree 8)\n");
    TRY(rmf_rrmf_quintic_solutions(p0, t0, p1, t1, 4.325, solutions, 4, &n));
    for (i = 0; i < n; i++)
        printf("  Example 1, eta = %.3f: rho = %.4f, L = %.4f, E = %.4f, E_rmf = %.4f\n", solutions[i].eta,
               solutions[i].rho, solutions[i].arc_length, solutions[i].energy_frenet, solutions[i].energy_rmf);
    TRY(rmf_rrmf_quintic_best(p0, t0, p1, t1, RMF_RRMF_MEASURE_SCALED_ENERGY_RMF, 90, &best, &admissible));
    printf("  Example 1, least L*E_rmf (%zu of 90 sampled eta admit solutions): eta = %.4f, L = %.4f\n", admissible,
           best.eta, best.arc_length);

    for (k = 0; k < 10; k++) {
        double s = k * 3.14159265358979323846 / 2;
        points[k].x = sin(s), points[k].y = cos(s), points[k].z = s;
        tangents[k].x = cos(s), tangents[k].y = -sin(s), tangents[k].z = 1;
    }
    TRY(rmf_rrmf_spline_hermite(points, tangents, 10, up, RMF_RRMF_MEASURE_SCALED_ENERGY_RMF, 64, &spline, &frames));
    TRY(rmf_curve_domain(spline, &t_min, &t_max));
    for (i = 0; i < SAMPLES; i++) {
        double s = t_min + (t_max - t_min) * (double)i / (SAMPLES - 1);
        TRY(rmf_curve_eval(spline, s, &x[i], NULL));
        TRY(rmf_frames_eval(frames, s, &t[i], &f2[i], &f3[i]));
    }
    for (k = 1; k < 9; k++) { /* the frame is continuous at the joints */
        RmfVec3 ta, fa, ga, tb, fb, gb;
        TRY(rmf_frames_eval(frames, nextafter((double)k, 0.0), &ta, &fa, &ga));
        TRY(rmf_frames_eval(frames, k, &tb, &fb, &gb));
        joint_gap = fmax(joint_gap, fabs(fa.x - fb.x) + fabs(fa.y - fb.y) + fabs(fa.z - fb.z));
    }
    vectors[0] = t, vectors[1] = f2, vectors[2] = f3;
    write_polyline_vtp("rrmf_helix_spline.vtp", x, SAMPLES, names, vectors, 3,
                       "RRMF quintic spline (Example 3) with its exact RMF");
    write_ribbon("rrmf_ribbon.obj", x, f2, SAMPLES, 0.3, "strip along the exact rational RMF vector f2");
    printf("  helix spline: 9 quintic segments, frame continuous at the joints (gap %.1e)\n", joint_gap);

    for (i = 0; i < 9; i++) {
        circle_poles[i].x = 0.3 * ring[i][0], circle_poles[i].y = 0.3 * ring[i][1], circle_poles[i].z = 0;
        circle_weights[i] = ring[i][2] == 1 ? 1.0 : sqrt(0.5);
    }
    TRY(rmf_nurbs_curve_create(1, line_poles, NULL, 2, line_knots, 4, &line));
    TRY(rmf_nurbs_curve_create(2, circle_poles, circle_weights, 9, circle_knots, 12, &circle));
    TRY(rmf_sweep_surface(spline, frames, line, &strip));
    TRY(rmf_sweep_surface(spline, frames, circle, &tube));
    write_tessellation(strip, 8, 6, "rrmf_developable_strip",
                  "line swept with the RMF: a developable surface");
    write_tessellation(tube, 8, 6, "rrmf_tube", "circle swept with the RMF: a pipe, exact rational");
    rmf_surface_free(strip);
    rmf_surface_free(tube);
    rmf_curve_free(line);
    rmf_curve_free(circle);
    rmf_frames_free(frames);
    rmf_curve_free(spline);
}

/* ---- 4. a cone spline and its development ---- */

static void twisted_cubic(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    (void)user;
    point->x = t, point->y = t * t, point->z = t * t * t;
    tangent->x = 1, tangent->y = 2 * t, tangent->z = 3 * t * t;
}

/* Appends a boundary arc spline to an SVG path: each segment is a rational quadratic
 * circular arc (poles P0, P1, P2, weights w0, w1, w2; cos(theta/2) = w1 / sqrt(w0 w2)),
 * written as a true SVG arc, or a line where it is straight. `forward` = 0 walks it
 * backwards. y is flipped (SVG's y points down). */
static void svg_arcs(FILE *f, const RmfCurve *curve, int forward, double scale) {
    size_t n = 0, k;
    rmf_curve_segment_count(curve, &n);
    for (k = 0; k < n; k++) {
        RmfBezierCurve seg;
        RmfVec3 a, b, m;
        double c, half, radius, turn;
        TRY(rmf_curve_segment(curve, forward ? k : n - 1 - k, &seg));
        a = seg.poles[forward ? 0 : 2], m = seg.poles[1], b = seg.poles[forward ? 2 : 0];
        c = hypot(b.x - a.x, b.y - a.y);
        half = acos(fmin(1.0, seg.weights[1] / sqrt(seg.weights[0] * seg.weights[2])));
        turn = (m.x - a.x) * (b.y - m.y) - (m.y - a.y) * (b.x - m.x);
        if (half < 1e-9 || c == 0) {
            fprintf(f, " L %.9g %.9g", scale * b.x, -scale * b.y);
            continue;
        }
        radius = c / (2 * sin(half));
        /* large-arc 0 (every patch spans at most 120 degrees); the sweep flips with y. */
        fprintf(f, " A %.9g %.9g 0 0 %d %.9g %.9g", scale * radius, scale * radius, turn > 0 ? 0 : 1, scale * b.x,
                -scale * b.y);
    }
}

static void demo_cone_spline(void) {
    const double t_min = -0.3, t_max = 0.3, scale = 100;
    RmfConeSpline *spline = NULL, *flat = NULL;
    RmfConeApproximationOptions options;
    RmfSurface *surface = NULL;
    RmfCurve *cubic = NULL, *lower = NULL, *upper = NULL;
    RmfConePiece piece;
    RmfVec3 start;
    size_t pieces, k;
    double deviation;
    char path[1024];
    FILE *f;

    printf("4. cone spline approximating the tangent surface of (t, t^2, t^3), and its development\n");
    TRY(rmf_callback_curve_create(twisted_cubic, NULL, 0.2, 1.2, &cubic));
    TRY(rmf_cone_approximation_options_init(&options));
    options.tolerance = 1e-4;
    TRY(rmf_cone_spline_approximate_with_options(cubic, 0.5, 6.0, &options, &spline, &deviation));
    rmf_curve_free(cubic);
    TRY(rmf_cone_spline_piece_count(spline, &pieces));
    printf("  %zu cone pieces, max deviation %.2e from the surface (tolerance 1e-4)\n", pieces, deviation);
    TRY(rmf_cone_spline_surface(spline, t_min, t_max, &surface));
    write_tessellation(surface, 4, 8, "cone_spline", "cone spline surface (rulings are mesh lines)");

    /* The development: boundaries are planar arc splines, the rulings straight lines. */
    TRY(rmf_cone_spline_develop(spline, &flat));
    TRY(rmf_cone_spline_boundary(flat, t_min, &lower));
    TRY(rmf_cone_spline_boundary(flat, t_max, &upper));
    {
        /* The view box: the arcs lie in the hulls of their Bézier poles (positive weights). */
        double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
        const RmfCurve *edges[2];
        size_t e, j, n;
        edges[0] = lower, edges[1] = upper;
        for (e = 0; e < 2; e++) {
            TRY(rmf_curve_segment_count(edges[e], &n));
            for (k = 0; k < n; k++) {
                RmfBezierCurve seg;
                TRY(rmf_curve_segment(edges[e], k, &seg));
                for (j = 0; j <= seg.degree; j++) {
                    lo[0] = fmin(lo[0], scale * seg.poles[j].x), hi[0] = fmax(hi[0], scale * seg.poles[j].x);
                    lo[1] = fmin(lo[1], -scale * seg.poles[j].y), hi[1] = fmax(hi[1], -scale * seg.poles[j].y);
                }
            }
        }
        f = open_output("cone_spline_development.svg", path, sizeof path);
        fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"%.6g %.6g %.6g %.6g\">\n", lo[0] - 10,
                lo[1] - 10, hi[0] - lo[0] + 20, hi[1] - lo[1] + 20);
    }
    TRY(rmf_cone_spline_piece(flat, 0, &piece));
    start = piece.start_point;
    fprintf(f, "  <path fill=\"#cde\" stroke=\"black\" stroke-width=\"0.5\" d=\"M %.9g %.9g",
            scale * (start.x + t_min * piece.start_ruling.x), -scale * (start.y + t_min * piece.start_ruling.y));
    svg_arcs(f, lower, 1, scale);
    TRY(rmf_cone_spline_piece(flat, pieces - 1, &piece));
    fprintf(f, " L %.9g %.9g", scale * (piece.end_point.x + t_max * piece.end_ruling.x),
            -scale * (piece.end_point.y + t_max * piece.end_ruling.y));
    svg_arcs(f, upper, 0, scale);
    fprintf(f, " Z\"/>\n");
    for (k = 1; k < pieces; k++) { /* the shared rulings */
        TRY(rmf_cone_spline_piece(flat, k, &piece));
        fprintf(f, "  <line stroke=\"gray\" stroke-width=\"0.3\" x1=\"%.9g\" y1=\"%.9g\" x2=\"%.9g\" y2=\"%.9g\"/>\n",
                scale * (piece.start_point.x + t_min * piece.start_ruling.x),
                -scale * (piece.start_point.y + t_min * piece.start_ruling.y),
                scale * (piece.start_point.x + t_max * piece.start_ruling.x),
                -scale * (piece.start_point.y + t_max * piece.start_ruling.y));
    }
    fprintf(f, "</svg>\n");
    fclose(f);
    written(path, "its exact development: arcs and lines, in the plane");
    rmf_curve_free(lower);
    rmf_curve_free(upper);
    rmf_surface_free(surface);
    rmf_cone_spline_free(flat);
    rmf_cone_spline_free(spline);
}

/* ---- 5. profile surfaces along a PH cubic spline (Mäurer & Jüttler) ---- */

#define PH_DEMO_PI 3.14159265358979323846

/* A conical helix ((t/4 + 1) cos t, (t/4 + 1) sin t, 0.4 t): the spine, given analytically. */
static void conical_helix(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    double r = t / 4 + 1;
    (void)user;
    point->x = r * cos(t), point->y = r * sin(t), point->z = 0.4 * t;
    tangent->x = cos(t) / 4 - r * sin(t), tangent->y = sin(t) / 4 + r * cos(t), tangent->z = 0.4;
}

/* A trefoil knot: a closed spine. */
static void trefoil(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    (void)user;
    point->x = sin(t) + 2 * sin(2 * t), point->y = cos(t) - 2 * cos(2 * t), point->z = -sin(3 * t);
    tangent->x = cos(t) + 4 * cos(2 * t), tangent->y = -sin(t) + 4 * sin(2 * t), tangent->z = -3 * cos(3 * t);
}

static RmfCurve *bezier_profile(const RmfVec3 *poles, size_t count, const double *weights) {
    double knots[16];
    size_t i;
    RmfCurve *c = NULL;
    for (i = 0; i < count; i++) knots[i] = 0, knots[count + i] = 1;
    TRY(rmf_nurbs_curve_create((uint32_t)(count - 1), poles, weights, count, knots, 2 * count, &c));
    return c;
}

static void demo_profile_surfaces(void) {
    /* A moulding profile (cubic) and a square made of four lines (closed, symmetry order 4). */
    static const RmfVec3 moulding[4] = {{0.3, -0.2, 0}, {0.55, 0.05, 0}, {0.2, 0.3, 0}, {-0.25, 0.25, 0}};
    static const RmfVec3 square[5] = {{0.2, 0.2, 0}, {-0.2, 0.2, 0}, {-0.2, -0.2, 0}, {0.2, -0.2, 0}, {0.2, 0.2, 0}};
    static const double square_knots[7] = {0, 0, 1, 2, 3, 4, 4};
    RmfCurve *spine = NULL, *profile = bezier_profile(moulding, 4, NULL), *loop = NULL, *box = NULL;
    RmfFrames *rmf = NULL, *frenet = NULL, *closed = NULL;
    RmfSurface *surface = NULL, *frenet_surface = NULL, *closed_surface = NULL;
    RmfSingularityMargin margin;
    double distance = 0, angle = 0;
    size_t segments = 0, n = 0;

    printf("5. profile surfaces along PH cubic splines (exact rational NURBS, degree (m, 9))\n");
    TRY(rmf_ph_spline_approximate(NULL, conical_helix, NULL, 0, 4 * PH_DEMO_PI, 1e-4, &spine, &distance));
    TRY(rmf_curve_segment_count(spine, &segments));
    TRY(rmf_ph_rational_rmf(spine, (RmfVec3){0, 0, 1}, &rmf));
    TRY(rmf_ph_rmf_angle_error(rmf, NULL, 0, &n, &angle));
    TRY(rmf_sweep_singularity_margin(spine, rmf, profile, &margin));
    printf("  conical helix -> %zu PH cubics within %.1e; rational RMF within %.1e rad of the exact RMF; "
           "singularity margin %.3f\n",
           segments, distance, angle, margin.margin);
    TRY(rmf_sweep_surface(spine, rmf, profile, &surface));
    write_tessellation(surface, 12, 8, "profile_surface_rmf",
                       "profile surface: moulding swept with the rational RMF");
    TRY(rmf_ph_frenet_frames(spine, &frenet));
    TRY(rmf_sweep_surface(spine, frenet, profile, &frenet_surface));
    write_tessellation(frenet_surface, 12, 8, "profile_surface_frenet",
                       "the same moulding swept with the Frenet frame (twists, torn at joints)");

    /* A closed spine: the RMF does not close; a uniform extra twist, a quarter turn at most for a
     * square profile, makes the sweep seamless. */
    TRY(rmf_ph_spline_approximate(NULL, trefoil, NULL, 0, 2 * PH_DEMO_PI, 1e-4, &loop, &distance));
    TRY(rmf_nurbs_curve_create(1, square, NULL, 5, square_knots, 7, &box));
    TRY(rmf_ph_rational_rmf_twisted(loop, (RmfVec3){0, 0, 1}, 0, 4, &closed));
    TRY(rmf_sweep_surface(loop, closed, box, &closed_surface));
    write_tessellation(closed_surface, 2, 8, "closed_sweep_trefoil",
                       "square tube along a trefoil, closed without a seam");

    rmf_surface_free(surface);
    rmf_surface_free(frenet_surface);
    rmf_surface_free(closed_surface);
    rmf_frames_free(rmf);
    rmf_frames_free(frenet);
    rmf_frames_free(closed);
    rmf_curve_free(spine);
    rmf_curve_free(profile);
    rmf_curve_free(loop);
    rmf_curve_free(box);
}

/* ---- 6. exact rational RMF by Möbius transformations ---- */

static void demo_mobius(void) {
    static RmfVec3 x[SAMPLES], t[SAMPLES], f2[SAMPLES], f3[SAMPLES];
    const char *names[3] = {"tangent", "f2", "f3"};
    const RmfVec3 *vectors[3];
    RmfVec3 points[9], tangents[9], seed = {0, 0, 1};
    const RmfVec3 line[2] = {{-0.25, 0, 0}, {0.25, 0, 0}};
    const double line_knots[4] = {0, 0, 1, 1};
    RmfCurve *curve = NULL, *profile = NULL;
    RmfFrames *frames = NULL;
    RmfSurface *strip = NULL;
    RmfNurbsCurve view;
    double t0, t1;
    size_t i;

    printf("6. curve with an exact rational RMF by Möbius transformations (Bartoň, Jüttler & Wang)\n");
    for (i = 0; i < 9; i++) { /* a conical helix */
        double s = 0.8 * (double)i, r = 1.5 - 0.08 * s;
        points[i].x = r * cos(s), points[i].y = r * sin(s), points[i].z = 0.35 * s;
        tangents[i].x = -r * sin(s) - 0.08 * cos(s), tangents[i].y = r * cos(s) - 0.08 * sin(s), tangents[i].z = 0.35;
    }
    TRY(rmf_mobius_rrmf_hermite(points, tangents, 9, seed, &curve, &frames));
    TRY(rmf_curve_nurbs(curve, &view));
    TRY(rmf_curve_domain(curve, &t0, &t1));
    for (i = 0; i < SAMPLES; i++) {
        double s = t0 + (t1 - t0) * (double)i / (SAMPLES - 1);
        TRY(rmf_curve_eval(curve, s, &x[i], NULL));
        TRY(rmf_frames_eval(frames, s, &t[i], &f2[i], &f3[i]));
    }
    vectors[0] = t, vectors[1] = f2, vectors[2] = f3;
    write_polyline_vtp("mobius_curve_frames.vtp", x, SAMPLES, names, vectors, 3,
                       "rational curve (NURBS degree 6) with its exact rational RMF");
    TRY(rmf_nurbs_curve_create(1, line, NULL, 2, line_knots, 4, &profile));
    TRY(rmf_sweep_surface(curve, frames, profile, &strip));
    write_tessellation(strip, 2, 16, "mobius_strip", "developable strip x + v f2, exact rational surface");
    printf("  the curve: NURBS of degree %u with %zu poles through 9 points of a conical helix\n", view.degree,
           view.pole_count);
    rmf_surface_free(strip);
    rmf_curve_free(profile);
    rmf_frames_free(frames);
    rmf_curve_free(curve);
}

/* ---- 7. a pipe route: a wire of lines, arcs and a NURBS, swept into STEP solids ---- */

static RmfVec3 vec(double x, double y, double z) {
    RmfVec3 v;
    v.x = x, v.y = y, v.z = z;
    return v;
}

static RmfCurve *circle_profile(double r) {
    const double s = 0.70710678118654752440;
    const RmfVec3 p[9] = {{r, 0, 0},   {r, r, 0},   {0, r, 0},  {-r, r, 0}, {-r, 0, 0},
                          {-r, -r, 0}, {0, -r, 0}, {r, -r, 0}, {r, 0, 0}};
    const double w[9] = {1, s, 1, s, 1, s, 1, s, 1}, k[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    RmfCurve *c = NULL;
    TRY(rmf_nurbs_curve_create(2, p, w, 9, k, 12, &c));
    return c;
}

/* The pipe route of sections 7 and 9: a line along x, a tangent quarter arc of radius 5, a
 * line up y to (15, end_y, 0). */
static void pipe_route_edges(RmfEdge edges[3], double end_y) {
    const double s = 0.70710678118654752440;
    edges[0].kind = RMF_EDGE_LINE, edges[0].points[0] = vec(0, 0, 0), edges[0].points[1] = vec(10, 0, 0);
    edges[1].kind = RMF_EDGE_ARC, edges[1].points[0] = vec(10, 0, 0);
    edges[1].points[1] = vec(10 + 5 * s, 5 - 5 * s, 0), edges[1].points[2] = vec(15, 5, 0);
    edges[2].kind = RMF_EDGE_LINE, edges[2].points[0] = vec(15, 5, 0), edges[2].points[1] = vec(15, end_y, 0);
}

static void write_shape(const RmfShape *shape, const char *name, const char *what) {
    char path[512];
    RmfSweepReport r;
    size_t f;
    snprintf(path, sizeof path, "%s/%s.step", out_dir, name);
    TRY(rmf_shape_write_step(shape, path));
    written(path, what);
    TRY(rmf_shape_report(shape, &r));
    printf("  %zu faces, %s; PH splines within %.1e of the NURBS edge, frames within %.1e rad of the RMF, max |cos| "
           "between parameter lines %.1e, least singularity margin %.2f\n",
           r.face_count, rmf_shape_is_solid(shape) ? "a closed solid" : "a sheet", r.spine_distance, r.rmf_angle_error,
           r.max_parameter_cosine, r.singularity_margin);
    for (f = 0; f < rmf_shape_face_count(shape); f++) { /* the first lateral face as a mesh */
        RmfShapeFace face;
        TRY(rmf_shape_face(shape, f, &face));
        if (face.kind == RMF_FACE_SWEPT) {
            char mesh[256];
            snprintf(mesh, sizeof mesh, "%s_face%zu", name, f);
            write_tessellation(face.surface, 8, 8, mesh, "one lateral face (exact rational surface)");
            break;
        }
    }
}

static void demo_pipe_route(void) {
    const RmfVec3 poles[4] = {{15, 10, 0}, {15, 15, 0}, {20, 20, 5}, {25, 20, 5}};
    const RmfVec3 square[5] = {{0.7, 0.7, 0}, {-0.7, 0.7, 0}, {-0.7, -0.7, 0}, {0.7, -0.7, 0}, {0.7, 0.7, 0}};
    const double knots[8] = {0, 0, 0, 0, 1, 1, 1, 1}, square_knots[7] = {0, 0, 1, 2, 3, 4, 4};
    RmfCurve *nurbs = NULL, *outer = circle_profile(1.0), *inner = circle_profile(0.8), *duct = NULL;
    const RmfCurve *holes[1];
    RmfEdge edges[5];
    RmfWireSweepOptions options;
    RmfShape *pipe = NULL, *mitred = NULL;

    printf("7. wire sweeps into STEP solids: a pipe route (line, tangent arc, line, NURBS), a mitred duct\n");
    TRY(rmf_nurbs_curve_create(3, poles, NULL, 4, knots, 8, &nurbs));
    TRY(rmf_nurbs_curve_create(1, square, NULL, 5, square_knots, 7, &duct));
    memset(edges, 0, sizeof edges);
    pipe_route_edges(edges, 10);
    edges[3].kind = RMF_EDGE_CURVE, edges[3].curve = nurbs;
    holes[0] = inner;
    TRY(rmf_wire_sweep_options_init(&options));
    options.corner_radius = 2;
    TRY(rmf_wire_sweep(edges, 4, outer, holes, 1, &options, &pipe));
    write_shape(pipe, "pipe_route_hollow", "hollow pipe, circle r = 1 with a hole r = 0.8 (STEP solid)");
    /* A duct with a sharp corner: a polyline, mitred. */
    edges[0].points[1] = vec(10, 0, 0);
    edges[1].kind = RMF_EDGE_LINE, edges[1].points[0] = vec(10, 0, 0), edges[1].points[1] = vec(10, 10, 0);
    edges[2].kind = RMF_EDGE_LINE, edges[2].points[0] = vec(10, 10, 0), edges[2].points[1] = vec(10, 10, 8);
    options.corner = RMF_CORNER_MITER;
    TRY(rmf_wire_sweep(edges, 3, duct, NULL, 0, &options, &mitred));
    write_shape(mitred, "duct_mitred", "square duct with two mitred corners (STEP solid)");
    rmf_shape_free(mitred);
    rmf_shape_free(pipe);
    rmf_curve_free(duct);
    rmf_curve_free(inner);
    rmf_curve_free(outer);
    rmf_curve_free(nurbs);
}

/* ---- 8. sheet metal: a square-to-round hopper ---- */

/* Writes a part's file as the library renders it (RMF_SHEET_FORMAT_*). */
static void write_part_file(const RmfSheetPart *part, RmfSheetFormat format, const char *name, const char *what) {
    size_t length = 0;
    char path[1024], *text;
    FILE *f;
    TRY(rmf_sheet_part_export(part, format, NULL, 0, &length));
    text = malloc(length + 1);
    if (!text) fail("malloc", RMF_ERROR_INTERNAL);
    TRY(rmf_sheet_part_export(part, format, text, length + 1, &length));
    f = open_output(name, path, sizeof path);
    fwrite(text, 1, length, f);
    fclose(f);
    free(text);
    written(path, what);
}

static void demo_hopper(void) {
    const RmfVec3 square[5] = {{-100, -100, 0}, {100, -100, 0}, {100, 100, 0}, {-100, 100, 0}, {-100, -100, 0}};
    const double square_knots[7] = {0, 0, 1, 2, 3, 4, 4};
    const double xs[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, ys[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    const double circle_knots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    RmfVec3 circle[9], formed[32];
    RmfVec2 marks[32], back[32];
    double weights[9], worst = 0, cx = 0, cy = 0;
    RmfCurve *bottom = NULL, *top = NULL;
    RmfSheetPart *part = NULL;
    RmfSheetOptions options;
    RmfSheetReport report;
    RmfFlatEdge *edges;
    size_t count = 0, arcs = 0, bends = 0, i;

    printf("8. sheet metal: square-to-round hopper, 2 mm sheet, K-factor 0.4\n");
    for (i = 0; i < 9; i++) {
        circle[i].x = 20 + 60 * xs[i], circle[i].y = 60 * ys[i], circle[i].z = 150;
        weights[i] = i % 2 ? sqrt(0.5) : 1.0;
    }
    TRY(rmf_nurbs_curve_create(1, square, NULL, 5, square_knots, 7, &bottom));
    TRY(rmf_nurbs_curve_create(2, circle, weights, 9, circle_knots, 12, &top));
    TRY(rmf_sheet_options_init(&options));
    options.tolerance = 1e-4;
    options.thickness = 2;
    options.k_factor = 0.4;
    TRY(rmf_sheet_part_transition(bottom, top, &options, &part));
    TRY(rmf_sheet_part_report(part, &report));
    printf("  %zu pieces (flat triangles, corner cones), edges within %.1e / %.1e of the square / circle,\n"
           "  neutral layer %.2f mm from the inner face\n",
           report.pieces, report.edge_distance[0], report.edge_distance[1], report.neutral - report.inner);
    write_part_file(part, RMF_SHEET_FORMAT_STEP_SOLID, "hopper.step", "the formed part, a closed solid (STEP)");
    write_part_file(part, RMF_SHEET_FORMAT_DXF, "hopper.dxf", "its flat pattern for the cutter (DXF: CUT, BEND)");
    write_part_file(part, RMF_SHEET_FORMAT_SVG, "hopper.svg", "the flat pattern as a drawing (SVG, mm)");
    TRY(rmf_sheet_part_flat_pattern(part, NULL, 0, &count));
    edges = malloc(count * sizeof *edges);
    if (!edges) fail("malloc", RMF_ERROR_INTERNAL);
    TRY(rmf_sheet_part_flat_pattern(part, edges, count, &count));
    for (i = 0; i < count; i++) {
        arcs += edges[i].kind == RMF_FLAT_EDGE_ARC;
        bends += edges[i].layer == RMF_FLAT_BEND;
    }
    printf("  flat pattern: %zu outline edges (%zu arcs, the rest lines), %zu bend lines\n", count - bends, arcs,
           bends);
    /* A hole of radius 10 drilled in the flat blank, about the middle of the first bend line:
     * where it lands on the formed part (outer face), and back. */
    for (i = 0; i < count && edges[i].layer != RMF_FLAT_BEND; i++) {}
    if (i < count) cx = 0.5 * (edges[i].from.x + edges[i].to.x), cy = 0.5 * (edges[i].from.y + edges[i].to.y);
    for (i = 0; i < 32; i++) {
        marks[i].x = cx + 10 * cos(2 * PH_DEMO_PI * (double)i / 32);
        marks[i].y = cy + 10 * sin(2 * PH_DEMO_PI * (double)i / 32);
    }
    TRY(rmf_sheet_part_flat_to_surface(part, marks, 32, RMF_SHEET_LAYER_OUTER, formed, NULL));
    TRY(rmf_sheet_part_surface_to_flat(part, formed, 32, RMF_SHEET_LAYER_OUTER, 1e-9, back));
    for (i = 0; i < 32; i++) worst = fmax(worst, hypot(back[i].x - marks[i].x, back[i].y - marks[i].y));
    printf("  a hole of radius 10 in the flat pattern maps onto the formed outer face, e.g. (%.3f, %.3f, %.3f),\n"
           "  and back to the flat pattern within %.1e\n", formed[0].x, formed[0].y, formed[0].z, worst);
    free(edges);
    rmf_sheet_part_free(part);
    rmf_curve_free(bottom);
    rmf_curve_free(top);
}

/* Every lateral face of a shape tessellated into one VTK file (the pictures in docs/). */
static void write_shape_mesh(const RmfShape *shape, uint32_t v_steps, const char *name, const char *what) {
    RmfVec3 *points = NULL;
    uint32_t *triangles = NULL;
    size_t np = 0, nt = 0, f, k;
    for (f = 0; f < rmf_shape_face_count(shape); f++) {
        RmfShapeFace face;
        size_t fp, ft;
        TRY(rmf_shape_face(shape, f, &face));
        if (face.kind != RMF_FACE_SWEPT) continue;
        TRY(rmf_surface_tessellate(face.surface, 8, v_steps, NULL, 0, NULL, 0, &fp, &ft));
        points = (RmfVec3 *)realloc(points, (np + fp) * sizeof *points);
        triangles = (uint32_t *)realloc(triangles, 3 * (nt + ft) * sizeof *triangles);
        if (!points || !triangles) exit(1);
        TRY(rmf_surface_tessellate(face.surface, 8, v_steps, points + np, fp, triangles + 3 * nt, ft, &fp, &ft));
        for (k = 3 * nt; k < 3 * (nt + ft); k++) triangles[k] += (uint32_t)np;
        np += fp, nt += ft;
    }
    write_mesh_vtp(name, points, np, triangles, nt, what);
    free(points);
    free(triangles);
}

/* ---- 9. sweeps as users make them: a thread (Frenet frame), a taper (scale law), a bar
 *         turned by a guide curve, a baluster (scale knots), a pipe through sections, a
 *         sheet from an open profile ---- */

/* A helix of radius 5 rising 2 per turn about the z axis. */
static void thread_helix(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    const double h = 2 / (2 * PH_DEMO_PI);
    (void)user;
    point->x = 5 * cos(t), point->y = 5 * sin(t), point->z = h * t;
    tangent->x = -5 * sin(t), tangent->y = 5 * cos(t), tangent->z = h;
}

/* The largest distance of a face's edge u = 0 from the helix about z through its start with
 * the thread's rise per radian: 0 for a screw motion. */
static double off_helix(const RmfSurface *surface, double rise) {
    RmfVec3 p, start, du, dv;
    double worst = 0, a0, r0, last, turned = 0, u0, u1, v0, v1;
    int k;
    TRY(rmf_surface_domain(surface, &u0, &u1, &v0, &v1));
    TRY(rmf_surface_eval(surface, u0, v0, &start, &du, &dv));
    a0 = atan2(start.y, start.x), r0 = hypot(start.x, start.y), last = a0;
    for (k = 0; k <= 400; k++) {
        double a, d;
        TRY(rmf_surface_eval(surface, u0, v0 + (v1 - v0) * k / 400.0, &p, &du, &dv));
        a = atan2(p.y, p.x);
        d = a - last;
        turned += d - 2 * PH_DEMO_PI * floor((d + PH_DEMO_PI) / (2 * PH_DEMO_PI));
        last = a;
        worst = fmax(worst, hypot(hypot(p.x - r0 * cos(a0 + turned), p.y - r0 * sin(a0 + turned)),
                                  p.z - start.z - rise * turned));
    }
    return worst;
}

/* A helix of radius 3 rising 8 in one turn about the z axis: the guide of a bar. */
static void guide_helix(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    const double h = 8 / (2 * PH_DEMO_PI);
    (void)user;
    point->x = 3 * cos(t), point->y = 3 * sin(t), point->z = h * t;
    tangent->x = -3 * sin(t), tangent->y = 3 * cos(t), tangent->z = h;
}

/* Along the pipe route (line, arc, line): a square through a circle into a triangle
 * (sections), and an open arc swept into a sheet (a gutter). */
static void demo_sections_and_sheet(void) {
    const double s = 0.70710678118654752440, r = 0.8, c = 0.86602540378443864676;
    const RmfVec3 square[5] = {{0.6, 0.6, 0}, {-0.6, 0.6, 0}, {-0.6, -0.6, 0}, {0.6, -0.6, 0}, {0.6, 0.6, 0}};
    const RmfVec3 triangle[4] = {{0.9, 0, 0}, {-0.45, 0.9 * c, 0}, {-0.45, -0.9 * c, 0}, {0.9, 0, 0}};
    const double square_knots[7] = {0, 0, 1, 2, 3, 4, 4}, triangle_knots[6] = {0, 0, 1, 2, 3, 3};
    /* A half circle of radius 0.8 on the side of -f2 (below the planar route, whose f2 is
     * its plane's normal), open towards f2: the gutter's section. */
    const RmfVec3 half[5] = {{0, r, 0}, {-r, r, 0}, {-r, 0, 0}, {-r, -r, 0}, {0, -r, 0}};
    const double half_w[5] = {1, s, 1, s, 1}, half_knots[8] = {0, 0, 0, 1, 1, 2, 2, 2};
    RmfCurve *sq = NULL, *tri = NULL, *ci = circle_profile(0.7), *gutter_arc = NULL;
    RmfEdge edges[3];
    RmfWireSection sections[3];
    RmfWireSweepOptions options;
    RmfShape *through = NULL, *gutter = NULL;
    RmfShapeFace face;
    double off = 0;
    size_t f, at_station = 0;

    TRY(rmf_nurbs_curve_create(1, square, NULL, 5, square_knots, 7, &sq));
    TRY(rmf_nurbs_curve_create(1, triangle, NULL, 4, triangle_knots, 6, &tri));
    TRY(rmf_nurbs_curve_create(2, half, half_w, 5, half_knots, 8, &gutter_arc));
    memset(edges, 0, sizeof edges);
    pipe_route_edges(edges, 15);
    memset(sections, 0, sizeof sections);
    sections[0].at = 0, sections[0].profile = sq;
    sections[1].at = 0.5, sections[1].profile = ci;
    sections[2].at = 1, sections[2].profile = tri;
    TRY(rmf_wire_sweep_options_init(&options));
    TRY(rmf_wire_sweep_through(edges, 3, sections, 3, &options, &through));
    write_shape(through, "pipe_sections", "the pipe route through a square, a circle and a triangle (STEP solid)");
    write_shape_mesh(through, 16, "pipe_sections.vtp", "its lateral faces as one mesh");
    /* Half way along the route (length 20 + 2.5 pi) lies in the arc: the faces' edges there
     * are the circle of radius 0.7 about the route's point. */
    for (f = 0; f < rmf_shape_face_count(through); f++) {
        double u0, u1, v0, v1, v;
        int k, end;
        TRY(rmf_shape_face(through, f, &face));
        if (face.kind != RMF_FACE_SWEPT) continue;
        TRY(rmf_surface_domain(face.surface, &u0, &u1, &v0, &v1));
        for (end = 0; end < 2; end++) {
            RmfVec3 p, du, dv;
            double phi, centre_x, centre_y, d;
            v = end ? v1 : v0;
            TRY(rmf_surface_eval(face.surface, u0, v, &p, &du, &dv));
            /* The route's point half way: 10 + 2.5 pi - 10 = 2.5 pi into the arc of radius 5. */
            phi = 0.25 * PH_DEMO_PI;
            centre_x = 10 + 5 * sin(phi), centre_y = 5 - 5 * cos(phi);
            d = hypot(hypot(p.x - centre_x, p.y - centre_y), p.z);
            if (fabs(d - 0.7) > 1e-6) continue;
            at_station++;
            for (k = 0; k <= 16; k++) {
                TRY(rmf_surface_eval(face.surface, u0 + (u1 - u0) * k / 16.0, v, &p, &du, &dv));
                off = fmax(off, fabs(hypot(hypot(p.x - centre_x, p.y - centre_y), p.z) - 0.7));
            }
        }
    }
    printf("  the pipe route through a square, a circle half way and a triangle: %zu face edges at the\n"
           "  circle's station, on the circle within %.1e\n", at_station, off);
    TRY(rmf_wire_sweep_options_init(&options));
    options.solid = 0;
    TRY(rmf_wire_sweep(edges, 3, gutter_arc, NULL, 0, &options, &gutter));
    write_shape(gutter, "gutter", "an open half circle along the pipe route: a sheet (STEP shell)");
    write_shape_mesh(gutter, 16, "gutter.vtp", "its faces as one mesh");
    rmf_shape_free(gutter);
    rmf_shape_free(through);
    rmf_curve_free(gutter_arc);
    rmf_curve_free(ci);
    rmf_curve_free(tri);
    rmf_curve_free(sq);
}

/* A flat bar up the z axis whose width turns to point at a helical guide (a twisted bar:
 * its corners run on helices), and a baluster: a circle along a line through four scales. */
static void demo_guide_and_knots(void) {
    const RmfVec3 bar[5] = {{0.8, -0.15, 0}, {0.8, 0.15, 0}, {-0.8, 0.15, 0}, {-0.8, -0.15, 0}, {0.8, -0.15, 0}};
    const double bar_knots[7] = {0, 0, 1, 2, 3, 4, 4};
    /* (fraction of the length, scale): 1 at the foot, 1.6, 0.6, 1.3, 1 at the top. */
    const double knots[6] = {0.2, 1.6, 0.5, 0.6, 0.8, 1.3};
    const double r = 0.9, l = 8, ends[5] = {1, 1.6, 0.6, 1.3, 1}, at[5] = {0, 0.2, 0.5, 0.8, 1};
    RmfCurve *guide = NULL, *section = NULL, *circle = circle_profile(r);
    RmfEdge line, guide_edge;
    RmfWireSweepOptions options;
    RmfShape *twisted = NULL, *baluster = NULL;
    RmfShapeFace face;
    RmfSweepReport report;
    RmfVec3 samples[65];
    double distance, off = 0, off_scale = 0;
    size_t f;
    int k;

    TRY(rmf_ph_spline_approximate(NULL, guide_helix, NULL, 0, 2 * PH_DEMO_PI, 1e-6, &guide, &distance));
    TRY(rmf_nurbs_curve_create(1, bar, NULL, 5, bar_knots, 7, &section));
    memset(&line, 0, sizeof line);
    memset(&guide_edge, 0, sizeof guide_edge);
    line.kind = RMF_EDGE_LINE, line.points[0] = vec(0, 0, 0), line.points[1] = vec(0, 0, l);
    guide_edge.kind = RMF_EDGE_CURVE, guide_edge.curve = guide;
    TRY(rmf_wire_sweep_options_init(&options));
    options.frame = RMF_FRAME_GUIDE;
    options.guide_edges = &guide_edge, options.guide_edge_count = 1;
    TRY(rmf_wire_sweep(&line, 1, section, NULL, 0, &options, &twisted));
    write_shape(twisted, "bar_guided", "a flat bar up a line, turned to point at a helical guide (STEP solid)");
    write_shape_mesh(twisted, 64, "bar_guided.vtp", "its lateral faces as one mesh");
    for (k = 0; k <= 64; k++) {
        RmfVec3 tangent;
        guide_helix(2 * PH_DEMO_PI * k / 64.0, NULL, &samples[k], &tangent);
    }
    write_polyline_vtp("bar_guide.vtp", samples, 65, NULL, NULL, 0, "the guide helix, sampled");
    for (f = 0; f < rmf_shape_face_count(twisted); f++) {
        TRY(rmf_shape_face(twisted, f, &face));
        if (face.kind == RMF_FACE_SWEPT) off = fmax(off, off_helix(face.surface, l / (2 * PH_DEMO_PI)));
    }
    TRY(rmf_shape_report(twisted, &report));
    printf("  a bar turned by a helical guide: its corners run on helices within %.1e (frames within\n"
           "  %.1e rad of the guide's direction)\n", off, report.frame_error);
    TRY(rmf_wire_sweep_options_init(&options));
    options.scale_knots = knots, options.scale_knot_count = 3;
    TRY(rmf_wire_sweep(&line, 1, circle, NULL, 0, &options, &baluster));
    write_shape(baluster, "baluster", "a circle along a line through scales 1, 1.6, 0.6, 1.3, 1 (STEP solid)");
    write_shape_mesh(baluster, 8, "baluster.vtp", "its lateral faces as one mesh");
    for (f = 0; f < rmf_shape_face_count(baluster); f++) {
        double u0, u1, v0, v1;
        int i;
        TRY(rmf_shape_face(baluster, f, &face));
        if (face.kind != RMF_FACE_SWEPT) continue;
        TRY(rmf_surface_domain(face.surface, &u0, &u1, &v0, &v1));
        for (i = 0; i <= 8; i++)
            for (k = 0; k <= 8; k++) {
                RmfVec3 p, du, dv;
                double z, sigma;
                int j = 0;
                TRY(rmf_surface_eval(face.surface, u0 + (u1 - u0) * i / 8.0, v0 + (v1 - v0) * k / 8.0, &p, &du, &dv));
                z = p.z / l;
                while (j < 3 && z > at[j + 1]) j++;
                sigma = ends[j] + (ends[j + 1] - ends[j]) * (z - at[j]) / (at[j + 1] - at[j]);
                off_scale = fmax(off_scale, fabs(hypot(p.x, p.y) - r * sigma));
            }
    }
    printf("  a baluster through scales 1, 1.6, 0.6, 1.3, 1 at 0, 0.2, 0.5, 0.8, 1 of its height: its\n"
           "  sections are the circles of those radii, linear between, within %.1e\n", off_scale);
    rmf_shape_free(baluster);
    rmf_shape_free(twisted);
    rmf_curve_free(circle);
    rmf_curve_free(section);
    rmf_curve_free(guide);
    demo_sections_and_sheet();
}

static void demo_thread_and_taper(void) {
    const double rise = 2 / (2 * PH_DEMO_PI);
    /* The thread's ridge in the normal plane at the start: f2 is the principal normal
     * (towards the axis), so the apex (-0.6, 0) points out of the rod. */
    const RmfVec3 ridge[4] = {{0.1, -0.45, 0}, {0.1, 0.45, 0}, {-0.6, 0, 0}, {0.1, -0.45, 0}};
    const double ridge_knots[6] = {0, 0, 1, 2, 3, 3};
    RmfCurve *helix = NULL, *triangle = NULL, *circle = circle_profile(1.0);
    RmfEdge edges[3];
    RmfWireSweepOptions options;
    RmfShape *thread = NULL, *rmf = NULL, *taper = NULL;
    RmfShapeFace face;
    RmfSweepReport report;
    double distance, frenet_off = 0, rmf_off = 0;
    size_t f;

    printf("9. sweeps as users make them: a thread (Frenet frame), a tapered pipe (scale law), a bar\n"
           "   following a guide curve, a baluster (scale knots), a pipe through sections, a gutter\n"
           "   (an open profile)\n");
    TRY(rmf_ph_spline_approximate(NULL, thread_helix, NULL, 0, 6 * PH_DEMO_PI, 1e-5, &helix, &distance));
    TRY(rmf_nurbs_curve_create(1, ridge, NULL, 4, ridge_knots, 6, &triangle));
    memset(edges, 0, sizeof edges);
    edges[0].kind = RMF_EDGE_CURVE, edges[0].curve = helix;
    TRY(rmf_wire_sweep_options_init(&options));
    options.tolerance = 1e-5;
    options.frame = RMF_FRAME_FRENET;
    TRY(rmf_wire_sweep(edges, 1, triangle, NULL, 0, &options, &thread));
    write_shape(thread, "thread_frenet", "a thread ridge along a 3-turn helix, Frenet frame (STEP solid)");
    write_shape_mesh(thread, 1, "thread_frenet.vtp", "its lateral faces as one mesh");
    options.frame = RMF_FRAME_RMF;
    TRY(rmf_wire_sweep(edges, 1, triangle, NULL, 0, &options, &rmf));
    write_shape_mesh(rmf, 1, "thread_rmf.vtp", "the same ridge with the RMF: it turns against the screw motion");
    for (f = 0; f < rmf_shape_face_count(thread); f++) {
        TRY(rmf_shape_face(thread, f, &face));
        if (face.kind == RMF_FACE_SWEPT) frenet_off = fmax(frenet_off, off_helix(face.surface, rise));
        TRY(rmf_shape_face(rmf, f, &face));
        if (face.kind == RMF_FACE_SWEPT) rmf_off = fmax(rmf_off, off_helix(face.surface, rise));
    }
    TRY(rmf_shape_report(thread, &report));
    printf("  the ridge's edges are helices of the thread's pitch within %.1e (frames within %.1e rad of the\n"
           "  Frenet frame); with the RMF they stray %.2f from them\n", frenet_off, report.frame_error, rmf_off);
    /* The pipe route of section 7 (line, tangent arc, line), the circle tapering to 0.4. */
    pipe_route_edges(edges, 15);
    TRY(rmf_wire_sweep_options_init(&options));
    options.scale_start = 1, options.scale_end = 0.4;
    TRY(rmf_wire_sweep(edges, 3, circle, NULL, 0, &options, &taper));
    write_shape(taper, "pipe_tapered", "the pipe route, its circle scaled from 1 to 0.4 (STEP solid)");
    write_shape_mesh(taper, 8, "pipe_tapered.vtp", "its lateral faces as one mesh");
    rmf_shape_free(taper);
    rmf_shape_free(rmf);
    rmf_shape_free(thread);
    rmf_curve_free(circle);
    rmf_curve_free(triangle);
    rmf_curve_free(helix);
    demo_guide_and_knots();
}

int main(int argc, char **argv) {
    if (argc > 1) out_dir = argv[1];
    if (mkdir(out_dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "demo: cannot create %s: %s\n", out_dir, strerror(errno));
        return 1;
    }
    printf("rmfsurf %s demo, writing to %s/\n", rmf_version(), out_dir);
    demo_curve_and_frames();
    demo_tessellated_surface();
    demo_rrmf_quintics();
    demo_cone_spline();
    demo_profile_surfaces();
    demo_mobius();
    demo_pipe_route();
    demo_hopper();
    demo_thread_and_taper();
    return 0;
}
