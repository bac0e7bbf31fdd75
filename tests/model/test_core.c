#define _POSIX_C_SOURCE 200809L
/* Core conventions: status codes, version, matrix helpers, cglm converters. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "shadowwarp.h"
#include "shadowwarp_cglm.h"
#include "test_core.h"

START_TEST(status_messages_are_distinct_and_ranged) {
    static const int codes[] = {
#define X(name, value, msg) value,
        SWARP_STATUS_LIST(X)
#undef X
    };
    size_t n = sizeof codes / sizeof codes[0];
    ck_assert_int_eq(codes[0], 0);
    for (size_t i = 0; i < n; ++i) {
        const char* s = swarp_status_string((swarp_status)codes[i]);
        ck_assert_ptr_nonnull(s);
        ck_assert_str_ne(s, "unknown status");
        ck_assert_int_eq(swarp_status_is_error((swarp_status)codes[i]), codes[i] > 0 && codes[i] < 1000);
        for (size_t j = i + 1; j < n; ++j) {
            ck_assert_int_ne(codes[i], codes[j]);
            ck_assert_str_ne(swarp_status_name((swarp_status)codes[i]),
                             swarp_status_name((swarp_status)codes[j]));
        }
    }
    ck_assert_str_eq(swarp_status_string((swarp_status)424242), "unknown status");
    ck_assert_int_eq(swarp_status_is_error((swarp_status)424242), 1);
    ck_assert_str_eq(swarp_status_name(SWARP_ERR_CAPACITY), "SWARP_ERR_CAPACITY");
}
END_TEST

START_TEST(version_matches_header) {
    ck_assert_int_eq(swarp_version_number(), SWARP_VERSION_NUMBER);
    ck_assert_str_eq(swarp_version_string(), SWARP_VERSION_STRING);
}
END_TEST

static swarp_mat4 random_mat(unsigned* seed) {
    swarp_mat4 m;
    for (int i = 0; i < 16; ++i) m.m[i] = (double)rand_r(seed) / RAND_MAX * 2.0 - 1.0;
    for (int i = 0; i < 4; ++i) m.m[i * 5] += 3.0; /* diagonally dominant: invertible */
    return m;
}

START_TEST(invert_times_original_is_identity) {
    unsigned seed = 12345;
    for (int t = 0; t < 1000; ++t) {
        swarp_mat4 a = random_mat(&seed), ai, p;
        ck_assert_int_eq(swarp_mat4_invert(&a, &ai), SWARP_OK);
        ck_assert_int_eq(swarp_mat4_mul(&a, &ai, &p), SWARP_OK);
        for (int i = 0; i < 16; ++i) ck_assert_double_eq_tol(p.m[i], (i % 5 == 0) ? 1.0 : 0.0, 1e-12);
    }
    swarp_mat4 z;
    memset(&z, 0, sizeof z);
    swarp_mat4 untouched;
    for (int i = 0; i < 16; ++i) untouched.m[i] = 7.0;
    swarp_mat4 out = untouched;
    ck_assert_int_eq(swarp_mat4_invert(&z, &out), SWARP_ERR_SINGULAR);
    ck_assert_int_eq(memcmp(&out, &untouched, sizeof out), 0);
    z.m[3] = NAN;
    ck_assert_int_eq(swarp_mat4_invert(&z, &out), SWARP_ERR_NON_FINITE);
    ck_assert_int_eq(swarp_mat4_invert(NULL, &out), SWARP_ERR_NULL_POINTER);
}
END_TEST

START_TEST(to_float_keeps_column_major_and_rejects_overflow) {
    swarp_mat4 m;
    for (int i = 0; i < 16; ++i) m.m[i] = i + 0.5;
    float f[16] = {0};
    ck_assert_int_eq(swarp_mat4_to_float(&m, f), SWARP_OK);
    for (int i = 0; i < 16; ++i) ck_assert_float_eq(f[i], (float)(i + 0.5));
    m.m[7] = 1e300;
    float g[16] = {0};
    ck_assert_int_eq(swarp_mat4_to_float(&m, g), SWARP_ERR_NON_FINITE);
    for (int i = 0; i < 16; ++i) ck_assert_float_eq(g[i], 0.0f);
}
END_TEST

START_TEST(cglm_converters_round_trip_and_agree_on_order) {
    /* A translation built by cglm must land in m[12..14] of a swarp_mat4. */
    mat4 t;
    glm_translate_make(t, (vec3){1.0f, 2.0f, 3.0f});
    swarp_mat4 s;
    swarp_cglm_mat4_to_swarp(t, &s);
    ck_assert_double_eq(s.m[12], 1.0);
    ck_assert_double_eq(s.m[13], 2.0);
    ck_assert_double_eq(s.m[14], 3.0);
    swarp_vec3 p = {0, 0, 0};
    swarp_vec4 h;
    ck_assert_int_eq(swarp_mat4_transform(&s, &p, &h), SWARP_OK);
    ck_assert_double_eq(h.x, 1.0);
    mat4 back;
    swarp_cglm_mat4_from_swarp(&s, back);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) ck_assert_float_eq(back[c][r], t[c][r]);
    vec3 v = {4.0f, 5.0f, 6.0f};
    swarp_vec3 sv;
    swarp_cglm_vec3_to_swarp(v, &sv);
    vec3 w;
    swarp_cglm_vec3_from_swarp(&sv, w);
    ck_assert(glm_vec3_eqv(v, w));
}
END_TEST

int main(void) {
    Suite* s = suite_create("core");
    TCase* tc = tcase_create("conventions");
    tcase_add_test(tc, status_messages_are_distinct_and_ranged);
    tcase_add_test(tc, version_matches_header);
    tcase_add_test(tc, invert_times_original_is_identity);
    tcase_add_test(tc, to_float_keeps_column_major_and_rejects_overflow);
    tcase_add_test(tc, cglm_converters_round_trip_and_agree_on_order);
    suite_add_tcase(s, tc);
    suite_add_tcase(s, tcase_params());
    suite_add_tcase(s, tcase_error());
    suite_add_tcase(s, tcase_split());
    int failed = tu_run_suite(s);
    return failed ? EXIT_FAILURE : EXIT_SUCCESS;
}
