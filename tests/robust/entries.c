/* The table of every entry point the robustness tools exercise.  A stage
 * that lands adds its entries_<stage>.c and one line here. */
#include <string.h>

#include "swr.h"

extern const swr_entry swr_entries_core[];
/* stage tables: */
extern const swr_entry swr_entries_lixel[];
extern const swr_entry swr_entries_filter[];
extern const swr_entry swr_entries_geometry[];
extern const swr_entry swr_entries_plan[];
extern const swr_entry swr_entries_splits[];
extern const swr_entry swr_entries_extras[];

static const swr_entry* const tables[] = {
    swr_entries_core,
    swr_entries_lixel,
    swr_entries_filter,
    swr_entries_geometry,
    swr_entries_splits,
    swr_entries_plan,
    swr_entries_extras,
};

size_t swr_entry_count(void) {
    size_t n = 0;
    for (size_t t = 0; t < sizeof tables / sizeof tables[0]; ++t)
        for (const swr_entry* e = tables[t]; e->name; ++e) ++n;
    return n;
}
const swr_entry* swr_entry_at(size_t i) {
    for (size_t t = 0; t < sizeof tables / sizeof tables[0]; ++t)
        for (const swr_entry* e = tables[t]; e->name; ++e)
            if (i-- == 0) return e;
    return NULL;
}
const swr_entry* swr_entry_find(const char* name) {
    for (size_t i = 0, n = swr_entry_count(); i < n; ++i)
        if (strcmp(swr_entry_at(i)->name, name) == 0) return swr_entry_at(i);
    return NULL;
}
