// The public header compiles as C++17 with -Wall -Wextra -Wpedantic -Werror
// (tests/meson.build: cpp_std=c++17, warning_level=3, werror=true) and C++
// calls the library: extern "C" linkage, enums, structs, status strings.
// This caller sees the experimental section too (tests/meson.build passes
// -DSWARP_EXPERIMENTAL_API; tests/lang/c99_pedantic.c compiles without it).
#include "shadowwarp.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>

static_assert(std::is_standard_layout<swarp_camera>::value, "swarp_camera is standard layout");
static_assert(std::is_trivially_copyable<swarp_mat4>::value, "swarp_mat4 is trivially copyable");
static_assert(sizeof(swarp_status) == 4, "32-bit enum");
static_assert(sizeof(swarp_camera) == 13 * sizeof(double) + 16, "camera layout as in C");
#ifndef SWARP_EXPERIMENTAL_API
#error "tests/meson.build builds this caller with -DSWARP_EXPERIMENTAL_API"
#endif
static_assert(sizeof(swarp_polyhedron) == SWARP_POLY_SIZE, "polyhedron layout as in C");

int main() {
    swarp_mat4 a{}, inv{}, prod{};
    for (int i = 0; i < 16; ++i) a.m[i] = (i % 5 == 0) ? 2.0 : 0.0;
    a.m[12] = 5.0;  // translation x
    if (swarp_mat4_invert(&a, &inv) != SWARP_OK) return 1;
    if (swarp_mat4_mul(&a, &inv, &prod) != SWARP_OK) return 2;
    for (int i = 0; i < 16; ++i)
        if (std::fabs(prod.m[i] - ((i % 5 == 0) ? 1.0 : 0.0)) > 1e-15) return 3;
    swarp_vec3 p{1.0, 2.0, 3.0};
    swarp_vec4 o{};
    if (swarp_mat4_transform(&a, &p, &o) != SWARP_OK || o.x != 7.0 || o.w != 2.0) return 4;  // m[15] = 2
    // errors leave outputs untouched, also seen from C++
    swarp_mat4 zero{}, untouched{};
    untouched.m[0] = 42.0;
    if (swarp_mat4_invert(&zero, &untouched) != SWARP_ERR_SINGULAR || untouched.m[0] != 42.0) return 5;
    std::string name = swarp_status_name(SWARP_ERR_SINGULAR);
    if (name != "SWARP_ERR_SINGULAR") return 6;
    swarp_camera cam{};
    cam.fovy = 1.0;
    swarp_light light{};
    light.type = SWARP_LIGHT_DIRECTIONAL;
    (void)cam;
    (void)light;
    // an experimental function: the [RHS] §4.3 near plane from a measured min depth
    double near_adj = 0.0;
    if (swarp_mindepth_near(1.0, 100.0, 10.0, nullptr, &near_adj) != SWARP_OK || !(near_adj > 9.0 && near_adj < 10.0))
        return 7;
    std::printf("C++ caller ok (%s, %s)\n", swarp_version_string(), swarp_status_string(SWARP_OK));
    return 0;
}
