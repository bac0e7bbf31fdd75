/* placeholder until the core stage lands */
#include "cli.h"
int cmd_params(sw_args* a) { (void)a; fprintf(stderr, "not yet\n"); return 1; }
int cmd_curve(sw_args* a) { (void)a; fprintf(stderr, "not yet\n"); return 1; }
int cmd_report(sw_args* a) { (void)a; fprintf(stderr, "not yet\n"); return 1; }
