/* swtool: the command-line face of libshadowwarp.  Every subcommand takes
 * --json and then prints exactly one JSON object (docs/swtool.md). */
#include <stdio.h>
#include <string.h>

#include "cli.h"

typedef struct sw_cmd {
    const char* name;
    int (*fn)(sw_args*);
    const char* help;
} sw_cmd;

static const sw_cmd commands[] = {
    {"params", cmd_params, "every warp parameter for --near --far --fovy --gamma [--np --fp]"},
    {"curve", cmd_curve, "m_x, m_z along the view depth for a technique [--splits --scheme]"},
    {"report", cmd_report, "the default configuration: each technique's parameter and max error"},
    /* stage: geometry */
    {"setup", cmd_setup, "light view/projection/matrix for --eye --dir --box and a light (swarp_setup)"},

    {"measure", cmd_measure, "measured error m_s, m_t, sigma of --matrix at --points FILE (x y z nx ny nz)"},

    /* stage: lixel */
    {"lixel", cmd_lixel, "plane-stabilised light matrix M_l for --eye --dir --plane --light-pos|--light-dir"},

    /* stage: splits */
    {"cascade", cmd_cascade, "splits, per-split warp, error maxima, atlas [--splits --scheme --stabilize --curve]"},
    {"stabwalk", cmd_stabwalk, "texel coordinates of a fixed point while the camera moves [--res --steps]"},

    /* stage: plan */
    {"plan", cmd_plan, "the planner: --gamma/--eye/--dir.. --max-error --map --max-passes [--force W]"},
    {"bench-report", cmd_bench_report, "accuracy/cost report: tables and Pareto data [--out-dir D]"},

    /* stage: extras */
    {"cube", cmd_cube, "[KOZ] cube-map faces for a post-projective light --light x,y,z,w [--point]"},
    {"mindepth", cmd_mindepth, "[RHS] 4.3 adjusted near plane from --min D or a --file of linear depths"},

};

static void usage(FILE* f) {
    fprintf(f, "usage: swtool <command> [options] [--json]\n\ncommands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; ++i)
        fprintf(f, "  %-12s %s\n", commands[i].name, commands[i].help);
    fprintf(f, "\nlibshadowwarp %s; docs/swtool.md documents every command.\n", swarp_version_string());
}

int main(int argc, char** argv) {
    if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; ++i)
        if (strcmp(argv[1], commands[i].name) == 0) {
            sw_args a = {argc - 1, argv + 1, 0};
            a.json = cli_flag(&a, "json");
            return commands[i].fn(&a);
        }
    fprintf(stderr, "swtool: unknown command '%s'\n\n", argv[1]);
    usage(stderr);
    return 2;
}
