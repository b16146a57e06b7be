/*
 * The API from 8 threads at once: every thread builds its own handles and reads shared
 * ones, and its results must equal those computed on the main thread — NURBS curves with
 * double-reflection frames, and every capability (PH spline, rational RMF and sweep; Möbius
 * Hermite; RRMF quintics; cone spline fit and development), compared bit for bit through a
 * checksum of their exported data; then all threads fail at the same moment (a barrier) with
 * different arguments, and each must read its own message from rmf_last_error
 * (thread-local). Run under valgrind and the sanitizers like every abi_*.c.
 */
#define _POSIX_C_SOURCE 200809L

/* These tests call the deprecated wrappers on purpose (they keep working): no warning. */
#define RMF_DEPRECATED(note)
#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "nurbs_eval.h"
#include "rmf_check.h"

#define THREADS 8
#define SAMPLES 64

static const RmfVec3 POLES[6] = {{0, 0, 0}, {1, 2, 0.5}, {2, -1, 1}, {3, 1, -0.5}, {4, 0, 2}, {5, 2, 1}};
static const double WEIGHTS[6] = {1, 0.5, 2, 1, 0.7, 1};
static const double KNOTS[10] = {0, 0, 0, 0, 0.3, 0.3, 1.2, 1.2, 1.2, 1.2};

static RmfCurve *shared_curve;
static RmfFrames *shared_frames;
static RmfVec3 expected_points[SAMPLES], expected_f2[SAMPLES];
static pthread_barrier_t all_failed, all_checked;

typedef struct {
    int index;
    int failures;
    char message[256];
} Job;

static double param(int i) { return 1.2 * i / (SAMPLES - 1); }

/* The analytic curve (t, t², t³) for the cone spline fit. */
static void twisted_cubic(double t, void *user, RmfVec3 *point, RmfVec3 *tangent) {
    (void)user;
    *point = vec3(t, t * t, t * t * t);
    *tangent = vec3(1, 2 * t, 3 * t * t);
}

/* A checksum of a NURBS surface's data (any difference in any pole changes it). */
static double surface_sum(const RmfSurface *surface) {
    RmfNurbsSurface view;
    double sum = 0;
    size_t i;
    if (rmf_surface_nurbs(surface, &view) != RMF_OK) return nan_value();
    for (i = 0; i < view.pole_count_u * view.pole_count_v; i++)
        sum += (i + 1) * (view.poles[i].x + 2 * view.poles[i].y + 3 * view.poles[i].z) * view.weights[i];
    return sum;
}

static double frames_sum(const RmfFrames *frames, double t_max) {
    RmfVec3 t, f2, f3;
    double sum = 0;
    int i;
    for (i = 0; i <= 16; i++) {
        if (rmf_frames_eval(frames, t_max * i / 16, &t, &f2, &f3) != RMF_OK) return nan_value();
        sum += (i + 1) * (f2.x + 2 * f2.y + 3 * f3.z);
    }
    return sum;
}

/* Every capability once; the checksums of what it made (NaN for a failure). */
static void capabilities(double sums[5]) {
    const RmfVec3 up = {0, 0, 1}, p0 = {0, 0, 0}, t0 = {1, 0, 1}, p1 = {1, 1, 1}, t1 = {0, 1, 1};
    const RmfVec3 line[2] = {{0.1, 0, 0}, {0.3, 0.1, 0}};
    const double line_knots[4] = {0, 0, 1, 1};
    RmfVec3 points[5], tangents[5];
    RmfCurve *spine = NULL, *profile = NULL, *mobius = NULL;
    RmfFrames *rmf = NULL, *mobius_frames = NULL;
    RmfSurface *sweep = NULL, *flat_surface = NULL;
    RmfConeSpline *cone = NULL, *flat = NULL;
    RmfRrmfQuintic solutions[8];
    size_t count = 0, i;
    double max_error = 0;
    for (i = 0; i < 5; i++) {
        double t = 0.7 * i;
        points[i] = vec3(cos(t), sin(t), 0.4 * t);
        tangents[i] = vec3(-sin(t), cos(t), 0.4);
    }
    for (i = 0; i < 5; i++) sums[i] = nan_value();
    if (rmf_ph_spline_hermite(points, tangents, 5, &spine) == RMF_OK &&
        rmf_ph_rational_rmf(spine, up, &rmf) == RMF_OK &&
        rmf_nurbs_curve_create(1, line, NULL, 2, line_knots, 4, &profile) == RMF_OK &&
        rmf_sweep_surface(spine, rmf, profile, &sweep) == RMF_OK)
        sums[0] = surface_sum(sweep);
    if (rmf_mobius_rrmf_hermite(points, tangents, 5, up, &mobius, &mobius_frames) == RMF_OK)
        sums[1] = frames_sum(mobius_frames, 4.0);
    if (rmf_rrmf_quintic_solutions(p0, t0, p1, t1, 4.325, solutions, 8, &count) == RMF_OK) {
        sums[2] = 0;
        for (i = 0; i < count; i++) sums[2] += (i + 1) * (solutions[i].rho + solutions[i].energy_rmf);
    }
    if (rmf_cone_spline_approximate(NULL, twisted_cubic, NULL, 0.2, 1.2, 0.5, 6.0, 1e-3,
                                    RMF_CONE_RULE_MIN_VERTEX_DISTANCE, 1000, &cone, &max_error) == RMF_OK &&
        rmf_cone_spline_develop(cone, &flat) == RMF_OK &&
        rmf_cone_spline_surface(flat, -0.3, 0.3, &flat_surface) == RMF_OK)
        sums[3] = surface_sum(flat_surface);
    sums[4] = frames_sum(rmf, 4.0);
    rmf_surface_free(flat_surface);
    rmf_cone_spline_free(flat);
    rmf_cone_spline_free(cone);
    rmf_frames_free(mobius_frames);
    rmf_curve_free(mobius);
    rmf_surface_free(sweep);
    rmf_curve_free(profile);
    rmf_frames_free(rmf);
    rmf_curve_free(spine);
}

static double expected_sums[5];

static void *work(void *arg) {
    Job *job = (Job *)arg;
    RmfCurve *own = NULL;
    RmfFrames *own_frames = NULL;
    RmfVec3 seed = {0, 0, 1}, p, t, f2, f3;
    int i, round;
    for (round = 0; round < 20; round++) {
        if (rmf_nurbs_curve_create(3, POLES, WEIGHTS, 6, KNOTS, 10, &own) != RMF_OK ||
            rmf_double_reflection_frames(own, seed, 500, &own_frames) != RMF_OK) {
            job->failures++;
            break;
        }
        for (i = 0; i < SAMPLES; i++) {
            rmf_curve_eval(own, param(i), &p, NULL);
            if (ne_dist(p, expected_points[i]) != 0.0) job->failures++;
            rmf_frames_eval(own_frames, param(i), &t, &f2, &f3);
            if (ne_dist(f2, expected_f2[i]) != 0.0) job->failures++;
            /* The shared handles, read concurrently. */
            rmf_curve_eval(shared_curve, param(i), &p, NULL);
            rmf_frames_eval(shared_frames, param(i), &t, &f2, &f3);
            if (ne_dist(p, expected_points[i]) != 0.0 || ne_dist(f2, expected_f2[i]) != 0.0) job->failures++;
        }
        rmf_frames_free(own_frames);
        rmf_curve_free(own);
        own = NULL;
        own_frames = NULL;
    }
    for (round = 0; round < 3; round++) {
        double sums[5];
        capabilities(sums);
        for (i = 0; i < 5; i++)
            if (!(sums[i] == expected_sums[i])) job->failures++;
    }
    /* Every thread fails at once, each with its own parameter value. */
    if (rmf_curve_eval(shared_curve, 100.0 + job->index, &p, NULL) != RMF_ERROR_INVALID_INPUT) job->failures++;
    pthread_barrier_wait(&all_failed);
    snprintf(job->message, sizeof job->message, "%s", rmf_last_error());
    pthread_barrier_wait(&all_checked);
    return NULL;
}

int main(void) {
    pthread_t threads[THREADS];
    Job jobs[THREADS];
    RmfVec3 seed = {0, 0, 1}, t, f3;
    int i;
    CHECK_STATUS(rmf_nurbs_curve_create(3, POLES, WEIGHTS, 6, KNOTS, 10, &shared_curve), RMF_OK, "");
    CHECK_STATUS(rmf_double_reflection_frames(shared_curve, seed, 500, &shared_frames), RMF_OK, "");
    if (!shared_curve || !shared_frames) return rmf_check_exit_code("abi_threads");
    for (i = 0; i < SAMPLES; i++) {
        rmf_curve_eval(shared_curve, param(i), &expected_points[i], NULL);
        rmf_frames_eval(shared_frames, param(i), &t, &expected_f2[i], &f3);
    }
    capabilities(expected_sums);
    for (i = 0; i < 5; i++) {
        CHECK(expected_sums[i] == expected_sums[i], "every capability runs on the main thread");
        if (expected_sums[i] != expected_sums[i]) fprintf(stderr, "capability %d: %s\n", (int)i, rmf_last_error());
    }
    pthread_barrier_init(&all_failed, NULL, THREADS);
    pthread_barrier_init(&all_checked, NULL, THREADS);
    for (i = 0; i < THREADS; i++) {
        jobs[i].index = i;
        jobs[i].failures = 0;
        jobs[i].message[0] = '\0';
        CHECK(pthread_create(&threads[i], NULL, work, &jobs[i]) == 0, "thread started");
    }
    for (i = 0; i < THREADS; i++) {
        char own_value[32];
        pthread_join(threads[i], NULL);
        snprintf(own_value, sizeof own_value, "t = %d ", 100 + i);
        CHECK(jobs[i].failures == 0, "every thread computes what the main thread computed");
        CHECK(strstr(jobs[i].message, own_value) != NULL, "each thread reads its own last error");
        if (!strstr(jobs[i].message, own_value)) fprintf(stderr, "thread %d read \"%s\"\n", i, jobs[i].message);
    }
    printf("abi_threads: %d threads x (20 rounds of NURBS + double reflection, 3 rounds of every capability) agree "
           "bit for bit with the main thread; last errors are per thread\n",
           THREADS);
    pthread_barrier_destroy(&all_failed);
    pthread_barrier_destroy(&all_checked);
    rmf_frames_free(shared_frames);
    rmf_curve_free(shared_curve);
    return rmf_check_exit_code("abi_threads");
}
