/* Status codes and messages, generated from the X-macro lists in the public
 * header so numbers, names and messages cannot drift apart. */
#include "common/swarp_internal.h"

#define SW_MSG_CASE(name, value, message) \
    case name:                            \
        return message;
#define SW_NAME_CASE(name, value, message) \
    case name:                             \
        return #name;

SWARP_API const char* swarp_status_string(swarp_status status) {
    switch (status) {
        SWARP_STATUS_LIST(SW_MSG_CASE)
        default:
            return "unknown status";
    }
}

SWARP_API const char* swarp_status_name(swarp_status status) {
    switch (status) {
        SWARP_STATUS_LIST(SW_NAME_CASE)
        default:
            return "SWARP_UNKNOWN_STATUS";
    }
}

SWARP_API int swarp_status_is_error(swarp_status status) {
    int v = (int)status;
    return !(v == 0 || (v >= 1000 && v <= 1999));
}

SWARP_API int swarp_version_number(void) { return SWARP_VERSION_NUMBER; }
SWARP_API const char* swarp_version_string(void) { return SWARP_VERSION_STRING; }
