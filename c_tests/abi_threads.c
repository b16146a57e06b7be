/*
 * The API from 8 threads at once: every thread builds its own handles and reads shared
 * ones, and its results must equal those computed on the main thread; then all threads fail
 * at the same moment (a barrier) with different arguments, and each must read its own
 * message from rmf_last_error (thread-local). Run under valgrind and the sanitizers like
 * every abi_*.c.
 */
#define _POSIX_C_SOURCE 200809L

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
    printf("abi_threads: %d threads x 20 rounds agree with the main thread; last errors are per thread\n", THREADS);
    pthread_barrier_destroy(&all_failed);
    pthread_barrier_destroy(&all_checked);
    rmf_frames_free(shared_frames);
    rmf_curve_free(shared_curve);
    return rmf_check_exit_code("abi_threads");
}
