#include "extras.h"
int extras_cloning(extras_env* e, int test, extras_bench_row* rows, int* nrows) { (void)e; (void)test; (void)rows; (void)nrows; return 0; }
