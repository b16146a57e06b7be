/*
 * C99 tests of the RRMF quintic API (Farouki, Giannelli & Sestini): Example 1 of the paper
 * through rmf_rrmf_quintic_solutions, every returned solution checked independently of the
 * library — the RRMF conditions (7)-(8) and w from the reported α, β with <complex.h>, the
 * curve and its frames from their NURBS views with the suite's own evaluator — the choice
 * of η, Example 3 (helix spline), and bad input: each failure returns its status with a
 * message naming the argument and leaves out-pointers untouched; the work budget of
 * rmf_rrmf_spline_hermite_with_options. Runs under valgrind and
 * the sanitizers like every abi_*.c.
 */
#include <complex.h>
#include <math.h>
#include <stdlib.h>

#include "nurbs_eval.h"
#include "rmf_check.h"

static const double PI = 3.14159265358979323846;

/* A vector as a C99 compound literal. */
#define vec3(x, y, z) ((RmfVec3){(x), (y), (z)})



static double angle(RmfVec3 a, RmfVec3 b) { return atan2(ne_norm(ne_cross(a, b)), ne_dot(a, b)); }

/* Example 1 of the paper. */
static const RmfVec3 P0 = {0, 0, 0}, P1 = {1, 1, 1}, T0 = {1, 0, 1}, T1 = {0, 1, 1};

/* ---- independent checks of one solution ---- */

static double complex coefficient(const double *pairs, int k) { return pairs[2 * k] + I * pairs[2 * k + 1]; }

/* Quadratic Bernstein polynomial with complex coefficients at t. */
static double complex quadratic(const double *pairs, double t) {
    double s = 1 - t;
    return coefficient(pairs, 0) * s * s + coefficient(pairs, 1) * 2 * s * t + coefficient(pairs, 2) * t * t;
}

static double norm2(double complex z) { return creal(z) * creal(z) + cimag(z) * cimag(z); }

/* Relative residuals of (7) and (8), and the largest error of the reported w_k, all from
 * the struct alone. */
static void rrmf_residuals(const RmfRrmfQuintic *q, double *r7, double *r8, double *w_error) {
    double complex a0 = coefficient(q->alpha, 0), a1 = coefficient(q->alpha, 1), a2 = coefficient(q->alpha, 2);
    double complex b0 = coefficient(q->beta, 0), b1 = coefficient(q->beta, 1), b2 = coefficient(q->beta, 2);
    double n0 = norm2(a0) + norm2(b0), n2 = norm2(a2) + norm2(b2);
    double complex start = a0 * conj(a1) + b0 * conj(b1), end = conj(a1) * a2 + conj(b1) * b2;
    double lhs7 = n0 * norm2(end), rhs7 = n2 * norm2(start);
    double complex lhs8 = n0 * (a0 * b2 - a2 * b0), rhs8 = 2 * start * (a0 * b1 - a1 * b0);
    double complex w1 = (conj(a0) * a1 + conj(b0) * b1) / n0, w2 = end / start;
    *r7 = fabs(lhs7 - rhs7) / (lhs7 + rhs7);
    *r8 = cabs(lhs8 - rhs8) / (cabs(lhs8) + cabs(rhs8));
    *w_error = fmax(cabs(coefficient(q->w, 0) - 1.0), fmax(cabs(coefficient(q->w, 1) - w1), cabs(coefficient(q->w, 2) - w2)));
}

typedef struct {
    double rrmf, w, end_point, end_tangent, speed, defect, defect_per_length, orthonormality, start_normal;
} SolutionErrors;

static void worst(SolutionErrors *into, const SolutionErrors *e) {
    into->rrmf = fmax(into->rrmf, e->rrmf);
    into->w = fmax(into->w, e->w);
    into->end_point = fmax(into->end_point, e->end_point);
    into->end_tangent = fmax(into->end_tangent, e->end_tangent);
    into->speed = fmax(into->speed, e->speed);
    into->defect = fmax(into->defect, e->defect);
    into->defect_per_length = fmax(into->defect_per_length, e->defect_per_length);
    into->orthonormality = fmax(into->orthonormality, e->orthonormality);
    into->start_normal = fmax(into->start_normal, e->start_normal);
}

/* The NURBS view of one vector of rational frames. */
static RmfCurve *frame_vector(const RmfFrames *frames, uint32_t which, RmfNurbsCurve *view) {
    RmfCurve *c = NULL;
    CHECK_STATUS(rmf_frames_vector_curve(frames, which, &c), RMF_OK, "");
    if (c) CHECK_STATUS(rmf_curve_nurbs(c, view), RMF_OK, "");
    return c;
}

/* Frame checks at `samples` parameters of [t0, t1] from the NURBS views of the curve and of
 * f2, f3 (the suite's own evaluator): RMF defect f2' . f3 per unit parameter and per unit
 * length, orthonormality of (x'/|x'|, f2, f3). */
static void check_frames(const RmfCurve *curve, const RmfFrames *frames, int samples, SolutionErrors *e) {
    RmfNurbsCurve cv, f2v, f3v;
    RmfCurve *f2c, *f3c;
    int i;
    CHECK_STATUS(rmf_curve_nurbs(curve, &cv), RMF_OK, "");
    f2c = frame_vector(frames, RMF_FRAME_F2, &f2v);
    f3c = frame_vector(frames, RMF_FRAME_F3, &f3v);
    if (f2c && f3c) {
        double t_min = cv.knots[0], t_max = cv.knots[cv.knot_count - 1];
        for (i = 0; i < samples; i++) {
            double t = t_min + (t_max - t_min) * i / (samples - 1);
            RmfVec3 x[3], f2[3], f3[3], tangent;
            ne_curve_derivatives(&cv, t, x);
            ne_curve_derivatives(&f2v, t, f2);
            ne_curve_derivatives(&f3v, t, f3);
            tangent = ne_unit(x[1]);
            e->defect = fmax(e->defect, fabs(ne_dot(f2[1], f3[0])));
            e->defect_per_length = fmax(e->defect_per_length, fabs(ne_dot(f2[1], f3[0])) / ne_norm(x[1]));
            e->orthonormality = fmax(e->orthonormality, fabs(ne_dot(f2[0], f2[0]) - 1));
            e->orthonormality = fmax(e->orthonormality, fabs(ne_dot(f3[0], f3[0]) - 1));
            e->orthonormality = fmax(e->orthonormality, fabs(ne_dot(f2[0], f3[0])));
            e->orthonormality = fmax(e->orthonormality, fabs(ne_dot(f2[0], tangent)));
            e->orthonormality = fmax(e->orthonormality, ne_dist(ne_cross(tangent, f2[0]), f3[0]));
        }
    }
    rmf_curve_free(f2c);
    rmf_curve_free(f3c);
}

/* Everything the issue asks of a returned solution, measured independently. */
static SolutionErrors check_solution(RmfVec3 p0, RmfVec3 t0, RmfVec3 p1, RmfVec3 t1, const RmfRrmfQuintic *q,
                                     RmfVec3 normal) {
    SolutionErrors e = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    RmfCurve *curve = NULL;
    RmfFrames *frames = NULL;
    RmfNurbsCurve view;
    RmfVec3 start[3], end[3], tangent, f2, f3, projected;
    double r7, r8, size;
    int i;
    rrmf_residuals(q, &r7, &r8, &e.w);
    e.rrmf = fmax(r7, r8);
    CHECK(q->rho > 0 && q->alpha[1] == 0 && q->alpha[0] >= 0, "rho > 0, alpha_0 real >= 0");
    CHECK_STATUS(rmf_rrmf_quintic_curve(p0, t0, p1, t1, q, normal, &curve, &frames), RMF_OK, "");
    if (!curve || !frames) return e;
    CHECK_STATUS(rmf_curve_nurbs(curve, &view), RMF_OK, "");
    CHECK(view.degree == 5 && view.pole_count == 6, "a quintic Bézier curve");
    ne_curve_derivatives(&view, 0.0, start);
    ne_curve_derivatives(&view, 1.0, end);
    size = fmax(ne_dist(p0, p1), q->arc_length);
    e.end_point = fmax(ne_dist(start[0], p0), ne_dist(end[0], p1)) / size;
    e.end_tangent = fmax(angle(start[1], t0), angle(end[1], t1));
    /* The curve's hodograph is the Hopf image of the reported α, β: |x'| = |α|² + |β|². */
    for (i = 0; i <= 50; i++) {
        double t = i / 50.0, sigma = norm2(quadratic(q->alpha, t)) + norm2(quadratic(q->beta, t));
        RmfVec3 d[3];
        ne_curve_derivatives(&view, t, d);
        e.speed = fmax(e.speed, fabs(ne_norm(d[1]) - sigma) / sigma);
    }
    check_frames(curve, frames, 1000, &e);
    CHECK_STATUS(rmf_frames_eval(frames, 0.0, &tangent, &f2, &f3), RMF_OK, "");
    projected = ne_unit(ne_sub(normal, ne_scale(ne_unit(t0), ne_dot(normal, ne_unit(t0)))));
    e.start_normal = ne_dist(f2, projected);
    rmf_frames_free(frames);
    rmf_curve_free(curve);
    return e;
}

static void assert_errors(const SolutionErrors *e, const char *what) {
    CHECK(e->rrmf <= 1e-10, what);
    CHECK(e->w <= 1e-12, what);
    CHECK(e->end_point <= 1e-12, what);
    CHECK(e->end_tangent <= 1e-12, what);
    CHECK(e->speed <= 1e-12, what);
    CHECK(e->defect <= 1e-9, what);
    CHECK(e->defect_per_length <= 1e-9, what);
    CHECK(e->orthonormality <= 1e-12, what);
    CHECK(e->start_normal <= 1e-14, what);
}

static void print_errors(const char *what, const SolutionErrors *e) {
    printf("%s: RRMF (7)-(8) %.1e, w %.1e, end point %.1e, end tangent %.1e rad, |x'| vs |a|^2+|b|^2 %.1e,\n"
           "    RMF defect |f2'.f3| %.1e (per length %.1e), orthonormality %.1e, f2(0) %.1e\n",
           what, e->rrmf, e->w, e->end_point, e->end_tangent, e->speed, e->defect, e->defect_per_length,
           e->orthonormality, e->start_normal);
}

/* ---- Example 1 ---- */

static int rounds_to(double value, double printed, int decimals) {
    return fabs(value - printed) <= 0.5 * pow(10.0, -decimals);
}

static void check_printed(const double *pairs, const double printed[6], const char *what) {
    int k;
    for (k = 0; k < 6; k++)
        if (!rounds_to(pairs[k], printed[k], 4)) {
            fprintf(stderr, "%s[%d] = %.6f, the paper prints %.4f\n", what, k, pairs[k], printed[k]);
            CHECK(0, what);
        }
}

static const RmfRrmfQuintic *with_rho(const RmfRrmfQuintic *s, size_t n, double rho) {
    size_t i;
    for (i = 0; i < n; i++)
        if (rounds_to(s[i].rho, rho, 4)) return &s[i];
    return NULL;
}

static void test_example_1(void) {
    static const double eta[2] = {5.2, 4.325}, rho[2] = {1.9158, 0.9652};
    static const double alpha[2][6] = {{1.4194, 0, -0.7920, 0.4058, -0.9158, 2.5605},
                                       {1.5363, 0, 1.1372, 0.4334, 0.7595, 1.2735}};
    static const double beta[2][6] = {{0.4512, 0, 1.1392, 0.7361, -0.5593, -0.6590},
                                      {0.4883, 0, -0.0461, -0.2865, -0.4712, 0.0067}};
    static const double w[2][6] = {{1, 0, -0.2751, 0.4094, 1.1863, 1.5044}, {1, 0, 0.6637, 0.2024, 0.6024, 0.7542}};
    static const double measures[2][3] = {{2.3259, 44.509, 22.856}, {1.9070, 5.7495, 1.4641}};
    static const int measure_decimals[2][3] = {{4, 3, 3}, {4, 4, 4}};
    SolutionErrors all = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    int c;
    for (c = 0; c < 2; c++) {
        RmfRrmfQuintic s[8];
        const RmfRrmfQuintic *q;
        size_t n = 99, i;
        CHECK_STATUS(rmf_rrmf_quintic_solutions(P0, T0, P1, T1, eta[c], s, 8, &n), RMF_OK, "");
        CHECK(n == 2, "two solutions for each eta of Example 1");
        for (i = 0; i + 1 < n; i++) CHECK(s[i].rho < s[i + 1].rho, "solutions in increasing rho");
        q = with_rho(s, n, rho[c]);
        CHECK(q != NULL, "the paper's solution is among them");
        if (!q) continue;
        printf("Example 1, eta = %.4f: rho = %.6f, alpha = %.6f%+.6fi, %.6f%+.6fi, %.6f%+.6fi\n"
               "    L = %.6f (paper %.4f), E = %.6f (paper %.*f), E_rmf = %.6f (paper %.*f)\n",
               q->eta, q->rho, q->alpha[0], q->alpha[1], q->alpha[2], q->alpha[3], q->alpha[4], q->alpha[5],
               q->arc_length, measures[c][0], q->energy_frenet, measure_decimals[c][1], measures[c][1],
               q->energy_rmf, measure_decimals[c][2], measures[c][2]);
        CHECK(q->eta == eta[c], "eta is reported");
        check_printed(q->alpha, alpha[c], "alpha");
        check_printed(q->beta, beta[c], "beta");
        check_printed(q->w, w[c], "w");
        CHECK(rounds_to(q->arc_length, measures[c][0], measure_decimals[c][0]), "L as printed");
        CHECK(rounds_to(q->energy_frenet, measures[c][1], measure_decimals[c][1]), "E as printed");
        CHECK(rounds_to(q->energy_rmf, measures[c][2], measure_decimals[c][2]), "E_rmf as printed");
        for (i = 0; i < n; i++) {
            SolutionErrors e = check_solution(P0, T0, P1, T1, &s[i], vec3(0.3, -1, 0.2));
            worst(&all, &e);
        }
    }
    print_errors("Example 1, all four solutions", &all);
    assert_errors(&all, "Example 1 solutions are exact interpolants with an exact RMF");
}

/* Solutions over a grid of eta for data sets in general position. */
static void test_many_solutions(void) {
    static const RmfVec3 data[4][4] = {
        {{0.1, -0.2, 0.3}, {1, 0.4, -0.2}, {1.3, 0.5, 0.1}, {0.2, 1, 0.7}},
        {{5, 5, 5}, {-0.3, 1, 0.2}, {5.02, 4.99, 5.01}, {0.9, 0.1, -0.6}},
        {{0, 0, 0}, {0.2, 0.9, 0.4}, {-3, 1, 2}, {-1, 0.2, -0.3}},
        {{1, 2, 3}, {0.5, 0.5, 1}, {1.5, 2.2, 3.9}, {-0.2, 0.9, 0.6}},
    };
    SolutionErrors all = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    int d, k, count = 0;
    for (d = 0; d < 4; d++)
        for (k = 0; k < 16; k++) {
            RmfRrmfQuintic s[8];
            size_t n = 0, i;
            CHECK_STATUS(rmf_rrmf_quintic_solutions(data[d][0], data[d][1], data[d][2], data[d][3], 2 * PI * k / 16, s,
                                                    8, &n),
                         RMF_OK, "");
            for (i = 0; i < n && i < 8; i++) {
                SolutionErrors e = check_solution(data[d][0], data[d][1], data[d][2], data[d][3], &s[i], vec3(0, 0, 1));
                worst(&all, &e);
                count++;
            }
        }
    printf("%d solutions of 4 data sets x 16 eta:\n", count);
    print_errors("  worst", &all);
    CHECK(count >= 40, "enough solutions to prove something");
    assert_errors(&all, "every returned solution is exact");
}

/* ---- choosing eta ---- */

static void test_best(void) {
    RmfRrmfQuintic best, s[8];
    size_t admissible = 0, n = 0, i;
    int found = 0;
    CHECK_STATUS(rmf_rrmf_quintic_best(P0, T0, P1, T1, RMF_RRMF_MEASURE_SCALED_ENERGY_RMF, 90, &best, &admissible),
                 RMF_OK, "");
    printf("Example 1, least L*E_rmf over 90 sampled eta (%zu admit solutions): eta = %.4f, rho = %.4f, L = %.4f, "
           "E = %.4f, E_rmf = %.4f\n",
           admissible, best.eta, best.rho, best.arc_length, best.energy_frenet, best.energy_rmf);
    CHECK(admissible > 0 && admissible <= 90, "admissible count");
    CHECK(fabs(best.eta - 4.325) < 0.01, "the fair curve of the paper's Figure 1 (right)");
    CHECK_STATUS(rmf_rrmf_quintic_solutions(P0, T0, P1, T1, best.eta, s, 8, &n), RMF_OK, "");
    for (i = 0; i < n; i++) found |= memcmp(&s[i], &best, sizeof best) == 0;
    CHECK(found, "the best is one of the solutions at its eta");
    for (i = 0; i < 90; i++) {
        size_t m = 0, j;
        CHECK_STATUS(rmf_rrmf_quintic_solutions(P0, T0, P1, T1, 2 * PI * (double)i / 90, s, 8, &m), RMF_OK, "");
        for (j = 0; j < m; j++)
            CHECK(best.arc_length * best.energy_rmf <= s[j].arc_length * s[j].energy_rmf, "no sample is better");
    }
    CHECK_STATUS(rmf_rrmf_quintic_best(P0, T0, P1, T1, RMF_RRMF_MEASURE_ARC_LENGTH, 36, &best, NULL), RMF_OK, "");
    {
        SolutionErrors e = check_solution(P0, T0, P1, T1, &best, vec3(1, 0, 0));
        assert_errors(&e, "the shortest interpolant is exact");
    }
}

/* ---- Example 3: the helix spline ---- */

static void test_helix_spline(void) {
    RmfVec3 points[10], tangents[10];
    RmfCurve *curve = NULL;
    RmfFrames *frames = NULL, *dr = NULL;
    RmfNurbsCurve view;
    SolutionErrors e = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    double worst_point = 0, worst_tangent = 0, against_dr = 0, t_max;
    int k;
    for (k = 0; k < 10; k++) {
        double t = k * PI / 2;
        points[k] = vec3(sin(t), cos(t), t);
        tangents[k] = vec3(cos(t), -sin(t), 1);
    }
    CHECK_STATUS(rmf_rrmf_spline_hermite(points, tangents, 10, vec3(-1, 0, 0), RMF_RRMF_MEASURE_SCALED_ENERGY_RMF, 64,
                                         &curve, &frames),
                 RMF_OK, "");
    if (!curve || !frames) return;
    CHECK_STATUS(rmf_curve_nurbs(curve, &view), RMF_OK, "");
    CHECK(view.degree == 5 && view.pole_count == 9 * 5 + 1, "nine quintic segments");
    t_max = view.knots[view.knot_count - 1];
    CHECK(t_max == 9.0, "segment k on [k, k + 1]");
    for (k = 0; k < 10; k++) {
        RmfVec3 d[3];
        ne_curve_derivatives(&view, k, d);
        worst_point = fmax(worst_point, ne_dist(d[0], points[k]));
        worst_tangent = fmax(worst_tangent, angle(d[1], tangents[k]));
    }
    check_frames(curve, frames, 1000, &e);
    /* An independent RMF of the same curve: double reflection on 9,001 samples. */
    CHECK_STATUS(rmf_double_reflection_frames(curve, vec3(-1, 0, 0), 9001, &dr), RMF_OK, "");
    for (k = 0; k <= 900 && dr; k++) {
        RmfVec3 ta, a2, a3, tb, b2, b3;
        rmf_frames_eval(frames, 9.0 * k / 900, &ta, &a2, &a3);
        rmf_frames_eval(dr, 9.0 * k / 900, &tb, &b2, &b3);
        against_dr = fmax(against_dr, ne_dist(a2, b2));
    }
    printf("Example 3 (helix, 9 segments): points %.1e, tangents %.1e rad; RMF defect %.1e (per length %.1e), "
           "orthonormality %.1e, |f2 - f2(double reflection)| %.1e\n",
           worst_point, worst_tangent, e.defect, e.defect_per_length, e.orthonormality, against_dr);
    CHECK(worst_point <= 1e-12 * 9 * PI, "the spline interpolates the points");
    CHECK(worst_tangent <= 1e-12, "and the tangents");
    CHECK(e.defect <= 1e-9 && e.defect_per_length <= 1e-9, "one exact RMF along the spline");
    CHECK(e.orthonormality <= 1e-12, "orthonormal");
    CHECK(against_dr <= 1e-8, "it is the RMF double reflection approximates");
    rmf_frames_free(dr);
    rmf_frames_free(frames);
    rmf_curve_free(curve);
}

/* ---- planar data: flat stretches and straight segments ---- */

/* The helix (cos t, sin t, 0.3 t) moved rigidly so that it starts at p with unit tangent t
 * (rotation about t0 x t taking the helix's start tangent t0 to t): points and tangents at
 * t = step, 2 step, ..., n step. */
static void helix_from(RmfVec3 p, RmfVec3 t, int n, double step, RmfVec3 *points, RmfVec3 *tangents) {
    RmfVec3 t0 = ne_unit(vec3(0, 1, 0.3)), axis = ne_cross(t0, t);
    double s = ne_norm(axis), c = ne_dot(t0, t);
    int k;
    if (s > 0) axis = ne_scale(axis, 1 / s);
    for (k = 1; k <= n; k++) {
        double u = k * step;
        RmfVec3 v[2] = {vec3(cos(u) - 1, sin(u), 0.3 * u), ne_unit(vec3(-sin(u), cos(u), 0.3))};
        int j;
        for (j = 0; j < 2; j++) { /* Rodrigues' rotation by atan2(s, c) about axis */
            RmfVec3 w = v[j];
            v[j] = ne_add(ne_add(ne_scale(w, c), ne_scale(ne_cross(axis, w), s)),
                          ne_scale(axis, ne_dot(axis, w) * (1 - c)));
        }
        points[k - 1] = ne_add(p, v[0]);
        tangents[k - 1] = v[1];
    }
}

static void test_flat_stretch(void) {
    /* helix (2 segments), a planar circular arc (2), helix (2), a straight segment, helix (2),
     * an S-shaped planar segment (parallel tangents), helix (1): 12 points. */
    RmfVec3 points[12], tangents[12], a, ta, n, chord;
    RmfCurve *curve = NULL;
    RmfFrames *frames = NULL, *dr = NULL;
    RmfNurbsCurve view;
    SolutionErrors e = {0};
    RmfRrmfQuintic best;
    size_t admissible = 77;
    double worst_tangent = 0, worst_point = 0, against_dr = 0, flat = 0, size = 0;
    int k, m = 0;
    points[0] = vec3(1, 0, 0);
    tangents[0] = ne_unit(vec3(0, 1, 0.3));
    helix_from(points[0], tangents[0], 2, PI / 2, points + 1, tangents + 1);
    m = 3;
    a = points[m - 1];
    ta = tangents[m - 1];
    n = ne_unit(ne_sub(vec3(0.3, -0.2, 1), ne_scale(ta, ne_dot(vec3(0.3, -0.2, 1), ta))));
    for (k = 1; k <= 2; k++) { /* radius 1.2, s = 0.8, 1.6 rad */
        double s = 0.8 * k;
        points[m] = ne_add(a, ne_scale(ne_add(ne_scale(n, 1 - cos(s)), ne_scale(ta, sin(s))), 1.2));
        tangents[m++] = ne_add(ne_scale(ta, cos(s)), ne_scale(n, sin(s)));
    }
    helix_from(points[m - 1], tangents[m - 1], 2, PI / 2, points + m, tangents + m);
    m += 2;
    points[m] = ne_add(points[m - 1], ne_scale(tangents[m - 1], 2));
    tangents[m] = tangents[m - 1];
    m++;
    helix_from(points[m - 1], tangents[m - 1], 2, PI / 2, points + m, tangents + m);
    m += 2;
    ta = tangents[m - 1];
    n = ne_unit(ne_sub(vec3(0.3, -0.2, 1), ne_scale(ta, ne_dot(vec3(0.3, -0.2, 1), ta))));
    chord = ne_scale(ne_add(ne_scale(ta, cos(0.5)), ne_scale(n, sin(0.5))), 1.5);
    points[m] = ne_add(points[m - 1], chord);
    tangents[m] = ta;
    m++;
    helix_from(points[m - 1], tangents[m - 1], 1, PI / 2, points + m, tangents + m);
    m++;
    CHECK(m == 12, "12 points");
    for (k = 0; k < m; k++) size = fmax(size, ne_norm(points[k]));

    CHECK_STATUS(rmf_rrmf_spline_hermite(points, tangents, 12, vec3(0, 0, 1), RMF_RRMF_MEASURE_SCALED_ENERGY_RMF, 64,
                                         &curve, &frames),
                 RMF_OK, "planar segments");
    if (!curve || !frames) return;
    CHECK_STATUS(rmf_curve_nurbs(curve, &view), RMF_OK, "");
    for (k = 0; k < 12; k++) {
        RmfVec3 d[3];
        ne_curve_derivatives(&view, k, d);
        worst_point = fmax(worst_point, ne_dist(d[0], points[k]));
        worst_tangent = fmax(worst_tangent, angle(d[1], tangents[k]));
    }
    /* The arc's two segments (poles 10..20) stay in the plane of ta, n through points[2]. */
    {
        RmfVec3 normal = ne_unit(ne_cross(tangents[2], ne_sub(points[3], points[2])));
        for (k = 10; k <= 20; k++) {
            flat = fmax(flat, fabs(ne_dot(ne_sub(view.poles[k], points[2]), normal)));
        }
    }
    check_frames(curve, frames, 1100, &e);
    CHECK_STATUS(rmf_double_reflection_frames(curve, vec3(0, 0, 1), 22001, &dr), RMF_OK, "");
    for (k = 0; k <= 1100 && dr; k++) {
        RmfVec3 ta2, a2, a3, tb, b2, b3;
        rmf_frames_eval(frames, 11.0 * k / 1100, &ta2, &a2, &a3);
        rmf_frames_eval(dr, 11.0 * k / 1100, &tb, &b2, &b3);
        against_dr = fmax(against_dr, ne_dist(a2, b2));
    }
    printf("Flat stretches (helix, arc, helix, straight, helix, S, helix; 11 segments): points %.1e, tangents "
           "%.1e rad, arc off its plane %.1e; RMF defect %.1e (per length %.1e), orthonormality %.1e, "
           "|f2 - f2(double reflection)| %.1e\n",
           worst_point, worst_tangent, flat, e.defect, e.defect_per_length, e.orthonormality, against_dr);
    CHECK(worst_point <= 1e-12 * size, "the spline interpolates the points");
    CHECK(worst_tangent <= 1e-12, "and the tangents (G1 joints)");
    CHECK(flat <= 1e-12 * size, "the flat stretch is flat");
    CHECK(e.defect <= 1e-9 && e.defect_per_length <= 1e-9, "one exact RMF along the spline");
    CHECK(e.orthonormality <= 1e-12, "orthonormal");
    CHECK(against_dr <= 1e-8, "it is the RMF double reflection approximates");
    rmf_frames_free(dr);
    rmf_frames_free(frames);
    rmf_curve_free(curve);
    curve = NULL;
    frames = NULL;

    /* One planar segment: the planar quintic, recognized by rmf_rrmf_quintic_curve. */
    CHECK_STATUS(rmf_rrmf_quintic_best(P0, vec3(0, 1, 0), vec3(1, 0, 0), vec3(1, 2, 0), RMF_RRMF_MEASURE_ARC_LENGTH,
                                       10, &best, &admissible),
                 RMF_OK, "planar data");
    CHECK(admissible == 0 && best.eta == 0 && best.rho == 1, "the planar quintic: no eta sampled");
    CHECK(best.w[0] == 1 && best.w[1] == 0 && best.w[2] == 1 && best.w[5] == 0, "w = 1");
    CHECK(best.alpha[1] == 0 && best.alpha[3] == 0 && best.beta[5] == 0, "real alpha, beta");
    CHECK_STATUS(rmf_rrmf_quintic_curve(P0, vec3(0, 1, 0), vec3(1, 0, 0), vec3(1, 2, 0), &best, vec3(0, 0, 1), &curve,
                                        &frames),
                 RMF_OK, "the planar quintic's curve");
    if (curve && frames) {
        SolutionErrors f = {0};
        check_frames(curve, frames, 200, &f);
        CHECK(f.defect <= 1e-12 && f.orthonormality <= 1e-12, "its exact RMF");
    }
    rmf_frames_free(frames);
    rmf_curve_free(curve);
}

/* ---- the special case alpha_1 = 0 ---- */

static void test_special_case(void) {
    /* theta_f = theta_i = 0.3 and phi = 1.5: at eta = phi / 2 the solutions have alpha_1 = 0. */
    const double theta = 0.3;
    const double angle_phi = 1.5;
    RmfVec3 p0 = vec3(0, 0, 0), p1 = vec3(2, 0, 0), t0 = vec3(cos(theta), sin(theta), 0);
    RmfVec3 t1 = vec3(cos(theta), sin(theta) * cos(angle_phi), sin(theta) * sin(angle_phi));
    RmfRrmfQuintic s[4];
    double theta_i = 0, theta_f = 0, phi = 0;
    size_t n = 0, i;
    CHECK_STATUS(rmf_rrmf_quintic_angles(p0, t0, p1, t1, &theta_i, &theta_f, &phi), RMF_OK, "");
    CHECK(fabs(theta_i - theta) < 1e-15 && fabs(theta_f - theta) < 1e-15 && fabs(phi - angle_phi) < 1e-15,
          "canonical angles");
    CHECK_STATUS(rmf_rrmf_quintic_solutions(p0, t0, p1, t1, phi / 2, s, 4, &n), RMF_OK, "");
    CHECK(n == 2, "two solutions in the special case");
    for (i = 0; i < n; i++) {
        SolutionErrors e = check_solution(p0, t0, p1, t1, &s[i], vec3(0, 0, 1));
        CHECK(s[i].alpha[2] == 0 && s[i].alpha[3] == 0, "alpha_1 = 0");
        assert_errors(&e, "special-case solutions are exact");
    }
    /* Example 1: theta_i = theta_f = acos(2 / sqrt 6), phi = 4 pi / 3 (the paper's branch). */
    CHECK_STATUS(rmf_rrmf_quintic_angles(P0, T0, P1, T1, &theta_i, &theta_f, &phi), RMF_OK, "");
    CHECK(fabs(theta_i - acos(2 / sqrt(6.0))) < 1e-15 && fabs(phi - 4 * PI / 3) < 1e-14, "Example 1 angles");
    CHECK_STATUS(rmf_rrmf_quintic_angles(P0, T0, P1, T1, NULL, &theta_f, &phi), RMF_ERROR_NULL_POINTER, "theta_i");
    CHECK_STATUS(rmf_rrmf_quintic_angles(P0, vec3(1, 1, 1), P1, T1, &theta_i, &theta_f, &phi), RMF_ERROR_INVALID_INPUT,
                 "t0 is parallel");
}

/* ---- bad input ---- */

static void test_bad_input(void) {
    static char storage[2];
    RmfCurve *const curve_sentinel = (RmfCurve *)(void *)&storage[0];
    RmfFrames *const frames_sentinel = (RmfFrames *)(void *)&storage[1];
    RmfCurve *curve = curve_sentinel;
    RmfFrames *frames = frames_sentinel;
    RmfRrmfQuintic s[2], good, best;
    /* The helix of Example 3 at t = 0, π/2, π. */
    RmfVec3 points[3] = {{0, 1, 0}, {1, 0, PI / 2}, {0, -1, PI}}, tangents[3] = {{1, 0, 1}, {0, -1, 1}, {-1, 0, 1}};
    const RmfVec3 zero = {0, 0, 0}, X = {1, 0, 0}, Y = {0, 1, 0};
    size_t n = 77, admissible = 77;
    double nan = nan_value();

#define SOLUTIONS(p0, t0, p1, t1, eta, buf, cap, expected, mention)                                          \
    do {                                                                                                     \
        n = 77;                                                                                              \
        CHECK_STATUS(rmf_rrmf_quintic_solutions(p0, t0, p1, t1, eta, buf, cap, &n), expected, mention);     \
        CHECK(n == 77, "count is untouched on failure");                                                   \
    } while (0)

    SOLUTIONS(vec3(nan, 0, 0), T0, P1, T1, 1.0, s, 2, RMF_ERROR_INVALID_INPUT, "p0");
    SOLUTIONS(P0, T0, vec3(1, 1, inf_value()), T1, 1.0, s, 2, RMF_ERROR_INVALID_INPUT, "p1");
    SOLUTIONS(P0, zero, P1, T1, 1.0, s, 2, RMF_ERROR_INVALID_INPUT, "t0");
    SOLUTIONS(P0, T0, P1, vec3(0, nan, 1), 1.0, s, 2, RMF_ERROR_INVALID_INPUT, "t1");
    SOLUTIONS(P1, T0, P1, T1, 1.0, s, 2, RMF_ERROR_INVALID_INPUT, "p0 and p1 coincide");
    SOLUTIONS(P0, X, X, Y, 1.0, s, 2, RMF_ERROR_INVALID_INPUT, "t0 is parallel");
    SOLUTIONS(P0, Y, X, ne_scale(X, -1), 1.0, s, 2, RMF_ERROR_INVALID_INPUT, "t1 is parallel");
    SOLUTIONS(P0, Y, X, vec3(1, -1, 0), 1.0, s, 2, RMF_ERROR_INVALID_INPUT, "planar");
    SOLUTIONS(P0, T0, P1, T1, nan, s, 2, RMF_ERROR_INVALID_INPUT, "eta");
    SOLUTIONS(P0, T0, P1, T1, inf_value(), s, 2, RMF_ERROR_INVALID_INPUT, "eta");
    SOLUTIONS(P0, T0, P1, T1, 5.2, NULL, 2, RMF_ERROR_NULL_POINTER, "solutions");
    CHECK_STATUS(rmf_rrmf_quintic_solutions(P0, T0, P1, T1, 5.2, s, 2, NULL), RMF_ERROR_NULL_POINTER, "count");
    /* Too small: the count needed is reported, the buffer is not written. */
    s[0].eta = -1;
    n = 77;
    CHECK_STATUS(rmf_rrmf_quintic_solutions(P0, T0, P1, T1, 5.2, s, 1, &n), RMF_ERROR_BUFFER_TOO_SMALL, "2 solutions");
    CHECK(n == 2 && s[0].eta == -1, "count needed written, buffer untouched");
    n = 77;
    CHECK_STATUS(rmf_rrmf_quintic_solutions(P0, T0, P1, T1, 5.2, NULL, 0, &n), RMF_ERROR_BUFFER_TOO_SMALL, "capacity");
    CHECK(n == 2, "a capacity-0 call reports the count");
    /* An eta without solutions is no error. */
    n = 77;
    CHECK_STATUS(rmf_rrmf_quintic_solutions(P0, T0, P1, T1, 2.0, NULL, 0, &n), RMF_OK, "");
    CHECK(n == 0, "no solution for eta = 2 in Example 1");

    CHECK_STATUS(rmf_rrmf_quintic_solutions(P0, T0, P1, T1, 4.325, s, 2, &n), RMF_OK, "");
    good = s[0];
#define CURVE(p0, t0, p1, t1, sol, normal, expected, mention)                                               \
    do {                                                                                                    \
        curve = curve_sentinel;                                                                             \
        frames = frames_sentinel;                                                                           \
        CHECK_STATUS(rmf_rrmf_quintic_curve(p0, t0, p1, t1, sol, normal, &curve, &frames), expected, mention); \
        CHECK(curve == curve_sentinel && frames == frames_sentinel, "outputs untouched on failure");        \
    } while (0)
    CURVE(P0, T0, P1, T1, NULL, Y, RMF_ERROR_NULL_POINTER, "solution");
    CURVE(P0, T0, P1, vec3(0, 1, 2), &good, Y, RMF_ERROR_INVALID_INPUT, "not an interpolant");
    good.rho *= 1.001;
    CURVE(P0, T0, P1, T1, &good, Y, RMF_ERROR_INVALID_INPUT, "not an interpolant");
    good.rho = nan;
    CURVE(P0, T0, P1, T1, &good, Y, RMF_ERROR_INVALID_INPUT, "rho");
    good = s[0];
    good.alpha[3] += 1e-3;
    CURVE(P0, T0, P1, T1, &good, Y, RMF_ERROR_INVALID_INPUT, "not an interpolant");
    good = s[0];
    CURVE(P0, T0, P1, T1, &good, T0, RMF_ERROR_INVALID_INPUT, "initial_normal");
    CURVE(P0, T0, P1, T1, &good, zero, RMF_ERROR_INVALID_INPUT, "initial_normal");
    CURVE(P0, T0, P1, T1, &good, vec3(nan, 1, 0), RMF_ERROR_INVALID_INPUT, "initial_normal");
    CURVE(P0, zero, P1, T1, &good, Y, RMF_ERROR_INVALID_INPUT, "t0");
    frames = frames_sentinel;
    CHECK_STATUS(rmf_rrmf_quintic_curve(P0, T0, P1, T1, &good, Y, NULL, &frames), RMF_ERROR_NULL_POINTER, "curve");
    CHECK(frames == frames_sentinel, "frames untouched");
    curve = curve_sentinel;
    CHECK_STATUS(rmf_rrmf_quintic_curve(P0, T0, P1, T1, &good, Y, &curve, NULL), RMF_ERROR_NULL_POINTER, "frames");
    CHECK(curve == curve_sentinel, "curve untouched");

    best.eta = -5;
#define BEST(p0, t0, p1, t1, measure, samples, expected, mention)                                            \
    do {                                                                                                     \
        admissible = 77;                                                                                     \
        CHECK_STATUS(rmf_rrmf_quintic_best(p0, t0, p1, t1, measure, samples, &best, &admissible), expected,  \
                     mention);                                                                               \
        CHECK(admissible == 77 && best.eta == -5, "outputs untouched on failure");                          \
    } while (0)
    BEST(P0, T0, P1, T1, RMF_RRMF_MEASURE_ARC_LENGTH, 0, RMF_ERROR_INVALID_INPUT, "eta_samples");
    BEST(P0, T0, P1, T1, RMF_RRMF_MEASURE_ARC_LENGTH, (size_t)-1, RMF_ERROR_INVALID_INPUT, "eta_samples");
    BEST(P0, T0, P1, T1, 5, 10, RMF_ERROR_INVALID_INPUT, "measure");
    BEST(P0, T0, P1, T1, 0xffffffffu, 10, RMF_ERROR_INVALID_INPUT, "measure");
    BEST(P0, vec3(cos(2.0), sin(2.0), 0), X, vec3(cos(3.1), sin(3.1) * cos(1.5), sin(3.1) * sin(1.5)),
         RMF_RRMF_MEASURE_ARC_LENGTH, 360, RMF_ERROR_NO_SOLUTION, "eta_samples = 360");
    CHECK_STATUS(rmf_rrmf_quintic_best(P0, T0, P1, T1, 0, 10, NULL, &admissible), RMF_ERROR_NULL_POINTER, "best");

#define SPLINE(pts, tans, count, normal, measure, samples, expected, mention)                                    \
    do {                                                                                                         \
        curve = curve_sentinel;                                                                                  \
        frames = frames_sentinel;                                                                                \
        CHECK_STATUS(rmf_rrmf_spline_hermite(pts, tans, count, normal, measure, samples, &curve, &frames), expected, \
                     mention);                                                                                   \
        CHECK(curve == curve_sentinel && frames == frames_sentinel, "outputs untouched on failure");            \
    } while (0)
    SPLINE(NULL, tangents, 3, Y, 3, 16, RMF_ERROR_NULL_POINTER, "points");
    SPLINE(points, NULL, 3, Y, 3, 16, RMF_ERROR_NULL_POINTER, "tangents");
    SPLINE(points, tangents, 1, Y, 3, 16, RMF_ERROR_INVALID_INPUT, "count");
    SPLINE(points, tangents, 0, Y, 3, 16, RMF_ERROR_INVALID_INPUT, "count");
    SPLINE(points, tangents, 3, Y, 3, 0, RMF_ERROR_INVALID_INPUT, "eta_samples");
    SPLINE(points, tangents, 3, Y, 7, 16, RMF_ERROR_INVALID_INPUT, "measure");
    SPLINE(points, tangents, 3, ne_scale(T0, 2), 3, 16, RMF_ERROR_INVALID_INPUT, "initial_normal");
    tangents[2] = vec3(nan, 0, 0);
    SPLINE(points, tangents, 3, Y, 3, 16, RMF_ERROR_INVALID_INPUT, "tangents[2]");
    tangents[2] = vec3(-1, 0, 1);
    points[2] = points[1];
    SPLINE(points, tangents, 3, Y, 3, 16, RMF_ERROR_INVALID_INPUT, "points[1] and points[2]");
    /* Segment 1 without an RRMF interpolant: theta_i = 2, theta_f = 3.1, phi = 1.5 about its
     * chord (planar data, refused before 0.2, are interpolated: test_flat_stretch). */
    {
        RmfVec3 t = ne_unit(tangents[1]), ex = ne_add(ne_scale(t, cos(2.0)), ne_scale(X, sin(2.0)));
        RmfVec3 ey = ne_unit(ne_sub(t, ne_scale(ex, ne_dot(t, ex)))), ez = ne_cross(ex, ey);
        points[2] = ne_add(points[1], ex);
        tangents[2] = ne_add(ne_scale(ex, cos(3.1)),
                             ne_scale(ne_add(ne_scale(ey, cos(1.5)), ne_scale(ez, sin(1.5))), sin(3.1)));
    }
    SPLINE(points, tangents, 3, Y, 3, 360, RMF_ERROR_NO_SOLUTION, "segment 1");
    CHECK_STATUS(rmf_rrmf_spline_hermite(points, tangents, 3, Y, 3, 16, NULL, &frames), RMF_ERROR_NULL_POINTER,
                 "curve");
}

/* ---- the work budget of rmf_rrmf_spline_hermite_with_options ---- */

/* Poles and weights of two curves' NURBS views are identical. */
static int same_curve(const RmfCurve *a, const RmfCurve *b) {
    RmfNurbsCurve x, y;
    if (rmf_curve_nurbs(a, &x) != RMF_OK || rmf_curve_nurbs(b, &y) != RMF_OK) return 0;
    return x.pole_count == y.pole_count && memcmp(x.poles, y.poles, x.pole_count * sizeof *x.poles) == 0 &&
           memcmp(x.weights, y.weights, x.pole_count * sizeof *x.weights) == 0;
}

/* The same spline as rmf_rrmf_spline_hermite, a report of the solves, a budget of exactly
   those solves giving the same spline, one solve less RMF_ERROR_NOT_CONVERGED with nothing
   written, and every bad option refused with a message naming its field. */
static void test_work_budget(void) {
    static char storage[2];
    RmfCurve *const curve_sentinel = (RmfCurve *)(void *)&storage[0];
    RmfFrames *const frames_sentinel = (RmfFrames *)(void *)&storage[1];
    RmfVec3 points[10], tangents[10];
    RmfCurve *plain = NULL, *curve = NULL, *again = NULL, *untouched = curve_sentinel;
    RmfFrames *plain_frames = NULL, *frames = NULL, *again_frames = NULL, *untouched_frames = frames_sentinel;
    RmfRrmfSplineOptions options, bad;
    RmfRrmfSplineReport report = {sizeof(RmfRrmfSplineReport), 0, 0, 0}, second = {sizeof(RmfRrmfSplineReport), 0, 0, 0};
    size_t spent;
    int k;
    for (k = 0; k < 10; k++) {
        double t = k * PI / 2;
        points[k] = vec3(sin(t), cos(t), t);
        tangents[k] = vec3(cos(t), -sin(t), 1);
    }
    CHECK_STATUS(rmf_rrmf_spline_options_init(&options), RMF_OK, "");
    CHECK(options.struct_size == sizeof options && options.measure == RMF_RRMF_MEASURE_SCALED_ENERGY_RMF &&
              options.eta_samples == 64 && options.max_evaluations == SIZE_MAX && options.initial_normal.x == 0 &&
              options.initial_normal.y == 0 && options.initial_normal.z == 0,
          "options_init writes the defaults");
    CHECK_STATUS(rmf_rrmf_spline_hermite_with_options(points, tangents, 10, &options, &untouched, &untouched_frames, NULL),
                 RMF_ERROR_INVALID_INPUT, "options->initial_normal");
    options.initial_normal = vec3(-1, 0, 0);
    options.eta_samples = 16;
    CHECK_STATUS(rmf_rrmf_spline_hermite_with_options(points, tangents, 10, &options, &curve, &frames, &report), RMF_OK,
                 "");
    CHECK_STATUS(rmf_rrmf_spline_hermite(points, tangents, 10, vec3(-1, 0, 0), RMF_RRMF_MEASURE_SCALED_ENERGY_RMF, 16,
                                         &plain, &plain_frames),
                 RMF_OK, "");
    CHECK(curve && plain && same_curve(curve, plain), "the same spline as rmf_rrmf_spline_hermite");
    CHECK(report.segments == 9, "the report counts the segments");
    CHECK(report.irregular_roots == 0, "the helix has no near-cusps");
    CHECK(report.evaluations >= 9 * 16 && report.evaluations <= 9 * (16 + 502),
          "eta_samples + at most 502 solves per segment");
    printf("rmf_rrmf_spline_hermite_with_options: Example 3 helix, 9 segments, N_eta = 16: %zu solves (%.1f per "
           "segment)\n",
           report.evaluations, report.evaluations / 9.0);
    spent = report.evaluations;
    options.max_evaluations = spent;
    CHECK_STATUS(rmf_rrmf_spline_hermite_with_options(points, tangents, 10, &options, &again, &again_frames, &second),
                 RMF_OK, "");
    CHECK(again && same_curve(again, curve) && second.evaluations == spent,
          "a budget of exactly the solves spent gives the same spline");
    options.max_evaluations = spent - 1;
    report.evaluations = 0;
    CHECK_STATUS(rmf_rrmf_spline_hermite_with_options(points, tangents, 10, &options, &untouched, &untouched_frames,
                                                      &report),
                 RMF_ERROR_NOT_CONVERGED, "budget");
    CHECK(strstr(rmf_last_error(), "segment 8") != NULL, "the message names the segment where the budget ran out");
    CHECK(untouched == curve_sentinel && untouched_frames == frames_sentinel && report.evaluations == 0,
          "a failing call writes neither the outputs nor the report");
    options.max_evaluations = 1;
    CHECK_STATUS(rmf_rrmf_spline_hermite_with_options(points, tangents, 10, &options, &untouched, &untouched_frames, NULL),
                 RMF_ERROR_NOT_CONVERGED, "segment 0");
    options.max_evaluations = SIZE_MAX;

#define BAD_OPTION(edit, expected, mention)                                                                        \
    do {                                                                                                          \
        bad = options;                                                                                            \
        edit;                                                                                                     \
        untouched = curve_sentinel;                                                                               \
        untouched_frames = frames_sentinel;                                                                       \
        CHECK_STATUS(rmf_rrmf_spline_hermite_with_options(points, tangents, 10, &bad, &untouched, &untouched_frames, \
                                                          NULL),                                                  \
                     expected, mention);                                                                          \
        CHECK(untouched == curve_sentinel && untouched_frames == frames_sentinel, "outputs untouched on failure"); \
    } while (0)
    BAD_OPTION(bad.struct_size = 0, RMF_ERROR_INVALID_INPUT, "options->struct_size");
    BAD_OPTION(bad.struct_size = sizeof bad + 8, RMF_ERROR_INVALID_INPUT, "options->struct_size");
    BAD_OPTION(bad.measure = 5, RMF_ERROR_INVALID_INPUT, "options->measure");
    BAD_OPTION(bad.eta_samples = 0, RMF_ERROR_INVALID_INPUT, "options->eta_samples");
    BAD_OPTION(bad.eta_samples = 1000001, RMF_ERROR_INVALID_INPUT, "options->eta_samples");
    BAD_OPTION(bad.max_evaluations = 0, RMF_ERROR_INVALID_INPUT, "options->max_evaluations");
    BAD_OPTION(bad.initial_normal = vec3(0, 0, 0), RMF_ERROR_INVALID_INPUT, "options->initial_normal");
    BAD_OPTION(bad.initial_normal = vec3(nan_value(), 0, 1), RMF_ERROR_INVALID_INPUT, "options->initial_normal");
    BAD_OPTION(bad.initial_normal = ne_scale(tangents[0], 3), RMF_ERROR_INVALID_INPUT, "options->initial_normal");
    report.struct_size = 0;
    CHECK_STATUS(rmf_rrmf_spline_hermite_with_options(points, tangents, 10, &options, &untouched, &untouched_frames,
                                                      &report),
                 RMF_ERROR_INVALID_INPUT, "report->struct_size");
    CHECK_STATUS(rmf_rrmf_spline_hermite_with_options(points, tangents, 10, NULL, &untouched, &untouched_frames, NULL),
                 RMF_ERROR_NULL_POINTER, "options");
    CHECK_STATUS(rmf_rrmf_spline_hermite_with_options(points, tangents, 10, &options, NULL, &untouched_frames, NULL),
                 RMF_ERROR_NULL_POINTER, "curve");
    CHECK_STATUS(rmf_rrmf_spline_hermite_with_options(NULL, tangents, 10, &options, &untouched, &untouched_frames, NULL),
                 RMF_ERROR_NULL_POINTER, "points");
    CHECK(untouched == curve_sentinel && untouched_frames == frames_sentinel, "outputs untouched on failure");
    CHECK_STATUS(rmf_rrmf_spline_options_init(NULL), RMF_ERROR_NULL_POINTER, "out");
    rmf_frames_free(again_frames);
    rmf_curve_free(again);
    rmf_frames_free(plain_frames);
    rmf_curve_free(plain);
    rmf_frames_free(frames);
    rmf_curve_free(curve);
}

/* Data with a start tangent 1e-3 rad off the chord: at every η one solution and one root
 * whose quintic nearly stops at the end (a near-cusp, speed ratio ~1e-12), which is not a
 * solution but is listed by rmf_rrmf_quintic_irregular_roots; the spline's report counts
 * such roots. */
static void test_irregular_roots(void) {
    const RmfVec3 p0 = {0, 0, 0}, t0 = {1, 1e-3, 0}, p1 = {1, 0, 0}, t1 = {0, 1, 1};
    RmfRrmfQuintic s[8];
    double rho[4] = {-1, -1, -1, -1}, ratio[4] = {-1, -1, -1, -1};
    size_t n = 0, m = 99, k, j;
    for (k = 0; k < 8; k++) {
        const double eta = 0.5 * k;
        CHECK_STATUS(rmf_rrmf_quintic_irregular_roots(p0, t0, p1, t1, eta, NULL, NULL, 0, &m), RMF_ERROR_BUFFER_TOO_SMALL, "");
        CHECK(m == 1, "one near-cusp at each eta");
        CHECK_STATUS(rmf_rrmf_quintic_irregular_roots(p0, t0, p1, t1, eta, rho, ratio, 4, &m), RMF_OK, "");
        CHECK(m == 1 && rho[0] > 0 && ratio[0] > 0 && ratio[0] < 1e-6 && rho[1] == -1,
              "the near-cusp's rho and speed ratio");
        CHECK_STATUS(rmf_rrmf_quintic_solutions(p0, t0, p1, t1, eta, s, 8, &n), RMF_OK, "");
        for (j = 0; j < n; j++) {
            CHECK(s[j].rho != rho[0], "the near-cusp is not among the solutions");
        }
    }
    {
        const RmfVec3 points[2] = {p0, p1}, tangents[2] = {t0, t1};
        RmfRrmfSplineOptions options;
        RmfRrmfSplineReport report = {sizeof(RmfRrmfSplineReport), 0, 0, 0};
        RmfCurve *curve = NULL;
        RmfFrames *frames = NULL;
        CHECK_STATUS(rmf_rrmf_spline_options_init(&options), RMF_OK, "");
        options.eta_samples = 16;
        options.initial_normal = vec3(0, 0, 1);
        CHECK_STATUS(rmf_rrmf_spline_hermite_with_options(points, tangents, 2, &options, &curve, &frames, &report),
                     RMF_OK, "");
        CHECK(report.irregular_roots >= 16, "the report counts the near-cusps of every sampled eta");
        rmf_frames_free(frames);
        rmf_curve_free(curve);
    }
}

int main(void) {
    test_example_1();
    test_many_solutions();
    test_best();
    test_helix_spline();
    test_flat_stretch();
    test_special_case();
    test_bad_input();
    test_work_budget();
    test_irregular_roots();
    return rmf_check_exit_code("abi_rrmf_quintic");
}
