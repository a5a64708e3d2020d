/* writers.c: the writers the driver knows (driver.h), from the list in
 * translate/meson.build ("writers"): writer_list.h, generated, defines
 * WRITERS as X(name) for each, and each writer's library defines
 * writer_<name> (writer.h). */
#include <stddef.h>
#include <string.h>

#include "driver.h"
#include "writer_list.h"

#define X(name) extern const writer_def writer_##name;
WRITERS
#undef X

#define X(name) &writer_##name,
const writer_def *const driver_writers[] = {WRITERS NULL};
#undef X

const writer_def *driver_writer(const char *name)
{
    for (size_t i = 0; driver_writers[i]; i++)
        if (strcmp(driver_writers[i]->name, name) == 0)
            return driver_writers[i];
    return NULL;
}
