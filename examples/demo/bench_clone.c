/* bench_clone.c -- demo-check --test bench-clone: K + 1 passes against
 * geometry cloning, timed. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "checks.h"

/* The machine line of the timing tables: cores, CPU, GL renderer. */
static void machine_line(char* out, size_t cap) {
    char model[160] = "unknown CPU";
    FILE* f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[256];
        while (fgets(line, sizeof line, f))
            if (!strncmp(line, "model name", 10)) {
                char* c = strchr(line, ':');
                if (c) {
                    c += 2;
                    c[strcspn(c, "\n")] = 0;
                    snprintf(model, sizeof model, "%s", c);
                }
                break;
            }
        fclose(f);
    }
    snprintf(out, cap, "%ld cores (nproc), %s; %s, OpenGL %s", sysconf(_SC_NPROCESSORS_ONLN), model,
             (const char*)glGetString(GL_RENDERER), (const char*)glGetString(GL_VERSION));
}

/* K + 1 passes against geometry cloning (1 + 1), K = 4, 8, 16, PSSM(K) +
 * LiSPSM on the default view: per frame the shadow passes and the main
 * pass, both glFinish-bracketed, both variants of one K in the same frame
 * loop (alternating which goes first) so load changes hit them alike;
 * medians over --frames (default 15).  Shaped like [RHS] Tables 7.1/7.2;
 * --bench-out FILE also writes the rows as TSV for swtool bench-report. */
int demo_bench_clone(const demo_options* o) {
    demo_view v;
    if (demo_preset_view(o, "default", &v)) return 1;
    demo_scene scene;
    demo_renderer r;
    if (demo_open_renderer(o, 1, &scene, &r)) return 1;
    const int F = o->frames > 0 ? o->frames : 15;
    double* t = malloc(sizeof(double) * 6 * (size_t)F);
    char machine[512];
    machine_line(machine, sizeof machine);
    FILE* tsv = NULL;
    if (o->bench_out && !(tsv = fopen(o->bench_out, "w"))) {
        fprintf(stderr, "demo: cannot write %s\n", o->bench_out);
        free(t);
        demo_render_free(&r);
        demo_scene_free(&scene);
        return 2;
    }
    if (tsv) {
        fprintf(tsv, "# demo-check --test bench-clone: geometry cloning vs K + 1 passes ([RHS] 3.3.6, Tables 7.1/7.2)\n");
        fprintf(tsv, "# machine\t%s\n", machine);
        fprintf(tsv, "# setup\t%dx%d\t%d\t%d\t%zu\n", v.w, v.h, o->map, F, scene.count / 3);
        fprintf(tsv, "# K\tvariant\tpasses\tshadow_ms\tmain_ms\tframe_ms\n");
    }
    printf("geometry cloning vs K + 1 passes: PSSM(K) + LiSPSM, default view, %dx%d, %d^2 maps, %zu "
           "triangles;\nmedian of %d frames, glFinish-bracketed ms; %s\n",
           v.w, v.h, o->map, scene.count / 3, F, machine);
    printf("%-40s %-9s %10s %10s %10s %7s %13s\n", "applied techniques", "3D passes", "shadow_ms",
           "main_ms", "frame_ms", "fps", "shadow ratio");
    int fails = 0;
    const int ks[3] = {4, 8, 16};
    for (int c = 0; c < 3 && t; ++c) {
        demo_shadow sh;
        if (demo_setup_for(o, &v, &scene.box, DEMO_TECH_PSSM_LISPSM, ks[c], &sh)) {
            ++fails;
            continue;
        }
        demo_main_params p;
        demo_main_params_for(&v, DEMO_MODE_SHADED, DEMO_FILTER_PCF3, 0.1f, &p);
        int errs = 0;
        /* t: [shadow, main, frame] x [K passes, clone] x F */
        for (int f = 0; f < F; ++f) {
            for (int j = 0; j < 2; ++j) {
                int clone = (j + f) % 2;
                double s = 0, m = 0;
                if (clone) {
                    errs += demo_render_shadow_single(&r, &sh, &s);
                } else {
                    double ms[DEMO_MAX_SPLITS];
                    errs += demo_render_shadow(&r, &sh, DEMO_FILTER_PCF3, ms);
                    for (int i = 0; i < sh.count; ++i) s += ms[i];
                }
                errs += demo_render_main(&r, &sh, &p, &m);
                t[(0 * 2 + clone) * F + f] = s;
                t[(1 * 2 + clone) * F + f] = m;
                t[(2 * 2 + clone) * F + f] = s + m;
            }
        }
        double med[3][2];
        for (int q = 0; q < 3; ++q)
            for (int cl = 0; cl < 2; ++cl) med[q][cl] = demo_median(t + (q * 2 + cl) * F, F);
        for (int cl = 0; cl < 2; ++cl) {
            char name[64], passes[16];
            snprintf(name, sizeof name, "%sPSSM(%d) + LiSPSM", cl ? "Geometry Cloning " : "", ks[c]);
            snprintf(passes, sizeof passes, cl ? "1 + 1" : "%d + 1", ks[c]);
            printf("%-40s %-9s %10.2f %10.2f %10.2f %7.2f %13.2f\n", name, passes, med[0][cl], med[1][cl],
                   med[2][cl], 1000.0 / med[2][cl], med[0][cl] / med[0][0]);
            if (tsv)
                fprintf(tsv, "%d\t%s\t%s\t%.4f\t%.4f\t%.4f\n", ks[c], cl ? "clone" : "passes", passes,
                        med[0][cl], med[1][cl], med[2][cl]);
        }
        if (errs) {
            printf("K=%d: %d GL errors FAIL\n", ks[c], errs);
            ++fails;
        }
    }
    if (!t) ++fails;
    if (tsv && fclose(tsv)) ++fails;
    free(t);
    demo_render_free(&r);
    demo_scene_free(&scene);
    return fails ? 1 : 0;
}
