/*
 * Corpus replay without libFuzzer (as zstd does): runs every file of
 * tests/fuzz/corpus/<entry>/ through the entry point's decoder and checks the
 * invariant (tests/robust/swr.h).  The corpus holds seeds and every crash
 * input ever found (crash-*), so each is a regression test in `meson test`.
 *   replay CORPUS_DIR [ENTRY...]
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../robust/swr.h"

static int replay_dir(const swr_entry* e, const char* dir, unsigned long* files, unsigned long* fails, int* skipped) {
    DIR* d = opendir(dir);
    if (!d) return 0;
    struct dirent* de;
    static swr_ctx c;
    static uint8_t buf[1 << 16];
    while ((de = readdir(d)) != NULL) {
        if (de->d_name[0] == '.') continue;
        char path[8192];
        if (snprintf(path, sizeof path, "%s/%s", dir, de->d_name) >= (int)sizeof path) continue;
        FILE* f = fopen(path, "rb");
        if (!f) continue;
        size_t n = fread(buf, 1, sizeof buf, f);
        fclose(f);
        int bad = swr_run(e, &c, buf, n);
        if (c.skipped) {
            *skipped = 1;
            break;
        }
        ++*files;
        if (bad) {
            ++*fails;
            printf("FAIL %s: %s\n", path, c.msg);
            if (c.args[0]) printf("     arguments: %s\n", c.args);
        }
    }
    closedir(d);
    return 1;
}

int main(int argc, char** argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: %s CORPUS_DIR [ENTRY...]\n", argv[0]);
        return 2;
    }
    unsigned long total = 0, fails = 0, dirs = 0;
    for (size_t i = 0; i < swr_entry_count(); ++i) {
        const swr_entry* e = swr_entry_at(i);
        if (argc > 2) {
            int want = 0;
            for (int k = 2; k < argc; ++k) want |= !strcmp(argv[k], e->name);
            if (!want) continue;
        }
        char dir[4096];
        snprintf(dir, sizeof dir, "%s/%s", argv[1], e->name);
        unsigned long files = 0, f0 = fails;
        int skipped = 0;
        if (!replay_dir(e, dir, &files, &fails, &skipped)) continue;
        if (skipped) {
            printf("%-34s skipped (not in the library yet)\n", e->name);
            continue;
        }
        ++dirs;
        total += files;
        printf("%-34s %6lu inputs %4lu failures\n", e->name, files, fails - f0);
    }
    printf("replayed %lu corpus inputs of %lu entry points, %lu failures\n", total, dirs, fails);
    return fails ? 1 : 0;
}
