/* What <windows.h> leaves behind: near and far as empty macros (from the
 * 16-bit pointer qualifiers) and min/max as function-like macros (without
 * NOMINMAX).  No public field or parameter of shadowwarp.h may be spelled
 * near, far, min or max, so the header must compile under these, with the
 * same layouts as without them. */
#define near
#define far
#define min(a, b) (((a) < (b)) ? (a) : (b))
#define max(a, b) (((a) > (b)) ? (a) : (b))
#define SWARP_EXPERIMENTAL_API 1
#include "shadowwarp.h"

/* The layouts, field by field (doubles are 8 bytes, uint32_t 4). */
#define WM_CAMERA_SIZE (3 * 24 + 4 * 8 + 4 * 4)
#define WM_ERROR_CONFIG_SIZE (7 * 8 + 4 * 4)
