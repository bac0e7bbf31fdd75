/* swtool (core stage): the warp techniques of the report and the curve, and
 * how each one's parameter maps to the n' of Lloyd's error model. */
#ifndef SWTOOL_CORE_TECH_H
#define SWTOOL_CORE_TECH_H

#include "cli.h"

typedef enum sw_tech {
    TECH_UNIFORM = 0, /* n' = inf, [RHS] (2.7)/(2.8) */
    TECH_PSM,         /* n' = n, [RHS] (2.5)/(2.6) */
    TECH_LISPSM,      /* lambda_LiSPSM [GMNPR] (9); = n_opt [RHS] (3.2) at gamma = 90 */
    TECH_REPAR,       /* n_repar [RHS] (3.3)-(3.5) */
    TECH_GMNPR,       /* lambda_GMNPR [GMNPR] (7)(8) */
    TECH_GLPR,        /* lambda_GLPR (F linear in z) */
    TECH_COUNT
} sw_tech;

typedef struct sw_tech_result {
    const char* param_name; /* "lambda_LiSPSM", "n_repar", ... */
    double param;           /* the technique's own parameter */
    double n_prime;         /* mapped to the error model (docs/parameters.md) */
    swarp_status status;    /* of the parameter function (OK or informational) */
} sw_tech_result;

const char* tech_name(sw_tech t);
/* 1 on success */
int tech_parse(const char* s, sw_tech* out);
/* theta = half fov, gamma = light/view angle in [0, pi/2], radians.
 * Returns the first error status, or SWARP_OK (r->status holds the info). */
swarp_status tech_eval(sw_tech t, double n, double f, double theta, double gamma,
                       sw_tech_result* r);

#endif
