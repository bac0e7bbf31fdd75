/*
 * Threads test: N threads call every entry point concurrently on shared
 * read-only inputs and must get results bit-identical to a single-threaded
 * run.  The inputs are the byte strings of K hard cases per entry point
 * (tests/robust/swr.h), generated once and shared by all threads; every call
 * decodes them, calls the library, checks the invariant and records its
 * outputs, which are hashed (FNV-1a over the bytes of the status and every
 * output double).  Each thread walks the cases from a different starting
 * point, several rounds, so the same function runs in several threads at
 * once.  The library has no globals; this catches any hidden state.
 *   threads [N_THREADS] [K]           default 8 threads, 300 cases per entry
 * (SWARP_THREADS_CASES overrides K: the valgrind run uses fewer)
 */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "swr.h"

typedef struct work_case {
    const swr_entry* e;
    uint8_t* bytes;
    size_t n;
    uint64_t hash;
} work_case;

static work_case* cases;
static size_t n_cases;
static int rounds = 3;

static uint64_t hash_ctx(const swr_ctx* c) {
    uint64_t h = 1469598103934665603ull;
    const uint8_t* p = (const uint8_t*)c->rec;
    for (size_t i = 0; i < c->n_rec * sizeof(double); ++i) h = (h ^ p[i]) * 1099511628211ull;
    h = (h ^ (uint64_t)(uint32_t)c->status) * 1099511628211ull;
    return h ^ (uint64_t)c->failed;
}

typedef struct thread_arg {
    int id;
    unsigned long mismatches, calls;
} thread_arg;

static void* worker(void* p) {
    thread_arg* a = (thread_arg*)p;
    swr_ctx* c = (swr_ctx*)malloc(sizeof *c);
    if (!c) return NULL;
    for (int r = 0; r < rounds; ++r)
        for (size_t k = 0; k < n_cases; ++k) {
            size_t i = (k + (size_t)a->id * (n_cases / 7 + 1) + (size_t)r * 13) % n_cases;
            swr_run(cases[i].e, c, cases[i].bytes, cases[i].n);
            ++a->calls;
            if (hash_ctx(c) != cases[i].hash) {
                if (a->mismatches < 5)
                    fprintf(stderr, "thread %d: %s differs from the single-threaded run\n", a->id, cases[i].e->name);
                ++a->mismatches;
            }
        }
    free(c);
    return NULL;
}

int main(int argc, char** argv) {
    int nthreads = argc > 1 ? atoi(argv[1]) : 8;
    unsigned long per = argc > 2 ? strtoul(argv[2], NULL, 0) : 300;
    const char* env = getenv("SWARP_THREADS_CASES"); /* valgrind runs fewer */
    if (env && *env) per = strtoul(env, NULL, 0);
    if (nthreads < 1 || nthreads > 256) return 2;
    swr_ctx* c = (swr_ctx*)malloc(sizeof *c);
    cases = (work_case*)calloc(swr_entry_count() * per, sizeof *cases);
    if (!c || !cases) return 2;
    size_t n_entries = 0;
    unsigned long inv = 0;
    for (size_t k = 0; k < swr_entry_count(); ++k) {
        const swr_entry* e = swr_entry_at(k);
        int used = 0;
        for (unsigned long j = 0; j < per; ++j) {
            swr_run_seeded(e, c, 0x7EAD5ull, j);
            if (c->skipped) break;
            used = 1;
            work_case* w = &cases[n_cases++];
            w->e = e;
            w->n = c->pos;
            w->bytes = (uint8_t*)malloc(w->n ? w->n : 1);
            if (!w->bytes) return 2;
            memcpy(w->bytes, c->buf, w->n);
            /* the single-threaded reference, from the same bytes */
            inv += (unsigned long)swr_run(e, c, w->bytes, w->n);
            w->hash = hash_ctx(c);
        }
        n_entries += (size_t)used;
    }
    pthread_t th[256];
    thread_arg args[256];
    for (int t = 0; t < nthreads; ++t) {
        args[t].id = t;
        args[t].mismatches = args[t].calls = 0;
        if (pthread_create(&th[t], NULL, worker, &args[t]) != 0) return 2;
    }
    unsigned long mism = 0, calls = 0;
    for (int t = 0; t < nthreads; ++t) {
        pthread_join(th[t], NULL);
        mism += args[t].mismatches;
        calls += args[t].calls;
    }
    printf("threads: %d threads, %zu entry points, %zu shared cases, %lu concurrent calls, %lu mismatches, "
           "%lu invariant violations\n",
           nthreads, n_entries, n_cases, calls, mism, inv);
    for (size_t i = 0; i < n_cases; ++i) free(cases[i].bytes);
    free(cases);
    free(c);
    return (mism || inv) ? 1 : 0;
}
