#include "extras.h"
int extras_blur(extras_env* e, int test) { (void)e; (void)test; return 0; }
