/*
 * libFuzzer target for every entry point of libshadowwarp.  One binary; the
 * entry point is chosen with the environment variable SWARP_FUZZ_TARGET
 * (e.g. swarp_warp_nopt).  The fuzzer's bytes go through the same decoder and
 * the same invariant as the hard-case sweep (tests/robust/swr.h): a
 * violation aborts, so libFuzzer keeps the input as a crash file.
 * Built and run by tests/fuzz/run.sh (clang -fsanitize=fuzzer,address,undefined).
 */
#include <stdio.h>
#include <stdlib.h>

#include "../robust/swr.h"

static const swr_entry* target;

int LLVMFuzzerInitialize(int* argc, char*** argv);
int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int LLVMFuzzerInitialize(int* argc, char*** argv) {
    (void)argc;
    (void)argv;
    const char* name = getenv("SWARP_FUZZ_TARGET");
    target = name ? swr_entry_find(name) : NULL;
    if (!target) {
        fprintf(stderr, "set SWARP_FUZZ_TARGET to one of:\n");
        for (size_t i = 0; i < swr_entry_count(); ++i) fprintf(stderr, "  %s\n", swr_entry_at(i)->name);
        exit(2);
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static swr_ctx c; /* libFuzzer runs one input at a time */
    if (swr_run(target, &c, data, size)) {
        fprintf(stderr, "invariant violated in %s: %s\n  arguments: %s\n", target->name, c.msg, c.args);
        abort();
    }
    return 0;
}
