/* [placeholder until the core stage lands] */
#include "swarp_internal.h"
typedef int sw_params_placeholder;
