/* Locale-independent text output for the explanation texts: a counting
 * builder and an exact decimal printer whose digits do not depend on the
 * caller's floating-point environment.  Not installed, not exported. */
#ifndef SWARP_DECIMAL_H
#define SWARP_DECIMAL_H

#include <stddef.h>
#include <stdint.h>

/* Text builder: counts always, writes only when asked (two runs: count, then
 * write, so a too-small buffer stays untouched). */
typedef struct sw_text {
    char* out;
    size_t n;
    int write;
} sw_text;

/* Appends the characters of s. */
void sw_puts(sw_text* t, const char* s);
/* Appends v in decimal, no sign, no leading zeros. */
void sw_putu(sw_text* t, uint64_t v);
/* Appends v with 3 significant digits ("0.532", "12.3", "4.19e+06", "inf",
 * "nan"); rounding half away from zero, decided exactly, so the text is the
 * same in every rounding mode and with subnormals flushed (DAZ). */
void sw_putd(sw_text* t, double v);

#endif
