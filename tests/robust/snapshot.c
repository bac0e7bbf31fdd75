/*
 * Snapshot of the robustness sweep's seeded cases: for every entry point and
 * every case index below K, the status and the recorded outputs (the same
 * values the threads and fenv tests compare), printed as one line per entry
 * with an FNV-1a hash over the bytes and, with -v, one line per case.
 *
 *   robust_snapshot [K] [-v]     default K = 2000
 *
 * Two builds of the library that give the same lines give bit-identical
 * outputs and statuses on every seeded case: docs/TESTING.md uses it to show
 * that a refactoring changed no result (diff the two outputs).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "swr.h"

static uint64_t fnv1a(uint64_t h, const void* p, size_t n) {
    const unsigned char* b = (const unsigned char*)p;
    for (size_t i = 0; i < n; ++i) {
        h ^= b[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

int main(int argc, char** argv) {
    unsigned long per = 2000;
    int verbose = 0;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "-v") == 0) verbose = 1;
        else per = strtoul(argv[i], NULL, 0);
    }
    swr_ctx* c = (swr_ctx*)malloc(sizeof *c);
    if (!c) return 2;
    for (size_t k = 0; k < swr_entry_count(); ++k) {
        const swr_entry* e = swr_entry_at(k);
        uint64_t h = 0xcbf29ce484222325ull;
        unsigned long ok = 0, err = 0;
        for (unsigned long j = 0; j < per; ++j) {
            swr_run_seeded(e, c, 0x5A9ull, j);
            if (c->skipped) break;
            int st = (int)c->status;
            uint64_t hc = fnv1a(0xcbf29ce484222325ull, &st, sizeof st);
            hc = fnv1a(hc, c->rec, c->n_rec * sizeof c->rec[0]);
            h = fnv1a(h, &hc, sizeof hc);
            if (swarp_status_is_error(c->status)) ++err;
            else ++ok;
            if (verbose) printf("%s %lu %s %016llx\n", e->name, j, swarp_status_name(c->status), (unsigned long long)hc);
        }
        printf("%-36s ok %6lu error %6lu hash %016llx\n", e->name, ok, err, (unsigned long long)h);
    }
    free(c);
    return 0;
}
