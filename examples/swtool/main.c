/* swtool: the command-line face of libshadowwarp.  Every subcommand takes
 * --json and then prints exactly one JSON object, whatever happens
 * (docs/swtool.md; the conventions are in cli.h). */
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
    {"cascade", cmd_cascade, "splits, per-split warp, error maxima, atlas; with --eye the scene form (swarp_cascade_setup)"},
    {"stabwalk", cmd_stabwalk, "texel coordinates of a fixed point while the camera moves [--map --steps]"},

    /* stage: plan */
    {"plan", cmd_plan, "the planner: --gamma or --eye/--dir/--light-dir, --max-error, --map, --max-passes [--force W]"},
    {"bench-report", cmd_bench_report, "accuracy/cost report: tables and Pareto data [--out-dir D]"},

    /* stage: extras */
    {"cube", cmd_cube, "[KOZ] cube-map faces for a post-projective light --light x,y,z,w [--point]"},
    {"mindepth", cmd_mindepth, "[RHS] 4.3 adjusted near plane from --min D or a --file of linear depths"},

};

static void usage(FILE* f) {
    fprintf(f, "usage: swtool COMMAND [OPTION...] [--json]\n"
               "       swtool help [COMMAND] | swtool COMMAND --help | swtool --version\n\ncommands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; ++i)
        fprintf(f, "  %-12s %s\n", commands[i].name, commands[i].help);
    fprintf(f, "\nOptions are --opt VALUE or --opt=VALUE, each at most once; with --json every outcome is one\n"
               "JSON object with \"status\".  Exit status: 0 success, 1 library error, 2 command-line mistake.\n"
               "libshadowwarp %s; docs/swtool.md and swtool(1) document every command.\n",
            swarp_version_string());
}

static const sw_cmd* find_command(const char* name) {
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; ++i)
        if (strcmp(name, commands[i].name) == 0) return &commands[i];
    return NULL;
}

static int has_json(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)
        if (strcmp(argv[i], "--json") == 0) return 1;
    return 0;
}

/* A mistake before any command runs (no command, an unknown one): the same
 * one JSON object as every other command-line mistake under --json. */
static int top_level_mistake(int argc, char** argv, const char* msg, const char* what) {
    fprintf(stderr, "swtool: %s%s%s\n\n", msg, what ? " " : "", what ? what : "");
    usage(stderr);
    if (has_json(argc, argv)) {
        char text[256];
        snprintf(text, sizeof text, "%s%s%s", msg, what ? " " : "", what ? what : "");
        json_begin();
        json_kv_str("status", "SWTOOL_ERR_USAGE");
        json_kv_str("message", text);
        json_end();
    }
    return CLI_EXIT_USAGE;
}

static int run_command(const sw_cmd* c, int argc, char** argv, int help) {
    static sw_args a; /* static: CLI_MAX_GIVEN entries, once per process */
    memset(&a, 0, sizeof a);
    a.argc = argc;
    a.argv = argv;
    a.summary = c->help;
    int rc = cli_parse(&a);
    if (rc != CLI_GO) return rc;
    if (help) a.help = 1;
    return c->fn(&a);
}

int main(int argc, char** argv) {
    if (argc < 2) return top_level_mistake(argc, argv, "a command is required", NULL);
    const char* first = argv[1];
    if (strcmp(first, "--help") == 0 || strcmp(first, "-h") == 0 ||
        (strcmp(first, "help") == 0 && argc == 2)) {
        usage(stdout);
        return CLI_EXIT_OK;
    }
    if (strcmp(first, "--version") == 0) {
        if (argc > 2) return top_level_mistake(argc, argv, "--version takes no arguments, got", argv[2]);
        printf("swtool (libshadowwarp) %s\n", swarp_version_string());
        return CLI_EXIT_OK;
    }
    if (strcmp(first, "help") == 0) {
        const sw_cmd* c = find_command(argv[2]);
        if (!c) return top_level_mistake(argc, argv, "help: unknown command", argv[2]);
        return run_command(c, argc - 2, argv + 2, 1);
    }
    const sw_cmd* c = find_command(first);
    if (!c) return top_level_mistake(argc, argv, "unknown command", first);
    return run_command(c, argc - 1, argv + 1, 0);
}
