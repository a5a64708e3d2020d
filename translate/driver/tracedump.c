/* tracedump.c: --dump, every selected frame and command of a trace on
 * standard output, with the decoder's damage said as the driver says it.
 */
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

#include "driver_internal.h"

/* Prints the commands of one sequence; adds its @NotRecorded counts to
 * unrec as frame `frame`'s. */
static bool dump_sequence(const driver_settings *d, const uint8_t *data, size_t size, uint64_t off,
                          const char *indent, const char *where, unrec_table *unrec,
                          uint64_t frame)
{
    rgl_cmd_iter it;
    rgl_cmd cmd;
    rgl_status st;
    char line[16384];
    rgl_cmd_iter_init(&it, data, size, off);
    while ((st = rgl_cmd_next(&it, &cmd)) == RGL_OK) {
        rgl_cmd_format(&cmd, line, sizeof line);
        printf("%s%" PRIu64 " @0x%" PRIx64 " %s\n", indent, cmd.index, cmd.offset, line);
        if (cmd.opcode == RGL_OP_NotRecorded)
            (void)unrec_add(unrec, cmd.arg[0].bytes, cmd.arg[0].count, cmd.arg[1].v.u, frame);
    }
    if (st == RGL_END)
        return true;
    printf("%s<damaged: %s>\n", indent, rgl_status_str(st));
    drv_say_decode_error(d, where, &it.error);
    return false;
}

static void dump_line(const char *text, void *user)
{
    (void)user;
    printf("#   %s\n", text);
}

int drv_dump(const driver_settings *d, rgl_reader *r)
{
    int status = 0;
    unrec_table unrec; /* the dumped frames' calls not recorded */
    unrec_init(&unrec);
    size_t isz;
    const char *info = rgl_reader_info(r, &isz);
    if (info) {
        printf("# info:\n");
        const char *p = info, *end = info + isz;
        while (p < end) {
            const char *nl = memchr(p, '\n', (size_t)(end - p));
            size_t len = nl ? (size_t)(nl - p) : (size_t)(end - p);
            printf("#   %.*s\n", (int)len, p);
            p += len + (nl ? 1 : 0);
        }
    }
    for (size_t i = 0; i < rgl_reader_frame_count(r); i++) {
        if (!frames_selected(d->ranges, d->nranges, i))
            continue;
        rgl_frame_info fi;
        rgl_error err;
        char where[64];
        snprintf(where, sizeof where, "frame %zu", i);
        if (rgl_reader_frame(r, i, &fi, &err) != RGL_OK) {
            printf("frame %zu: <damaged: %s>\n", i, rgl_status_str(err.status));
            drv_say_decode_error(d, where, &err);
            status = DRIVER_EXIT_INPUT;
            continue;
        }
        printf("frame %zu: stream %u, number %u, flags 0x%x%s%s, snapshot ", i, fi.stream,
               fi.number, fi.flags, fi.flags & RGL_FRAME_LIVE_CONTEXT ? " live-context" : "",
               fi.flags & RGL_FRAME_STATE_CARRIED ? " state-carried" : "");
        if (fi.state)
            printf("#%u", fi.state);
        else
            printf("none");
        printf(", @0x%" PRIx64 ", %zu bytes of commands\n", fi.offset, fi.commands_size);
        if (fi.state) {
            rgl_resource res;
            if (rgl_reader_resource(r, fi.state, &res, &err) != RGL_OK) {
                printf("  snapshot #%u: <damaged: %s>\n", fi.state, rgl_status_str(err.status));
                drv_say_decode_error(d, where, &err);
                status = DRIVER_EXIT_INPUT;
            } else {
                printf("  snapshot #%u: @0x%" PRIx64 ", %zu bytes\n", fi.state, res.data_offset,
                       res.size);
                char w2[96];
                snprintf(w2, sizeof w2, "frame %zu, snapshot #%u", i, fi.state);
                if (res.kind == RGL_RES_COMMANDS &&
                    !dump_sequence(d, res.data, res.size, res.data_offset, "    ", w2, &unrec, i))
                    status = DRIVER_EXIT_INPUT;
            }
        }
        if (!dump_sequence(d, fi.commands, fi.commands_size, fi.commands_offset, "  ", where,
                           &unrec, i))
            status = DRIVER_EXIT_INPUT;
    }
    if (unrec.n || unrec.other_calls) {
        /* Every one, marked by what it can change (no frame is translated
         * here to tell whether it does). */
        printf("# not recorded (@NotRecorded) in these frames:\n");
        unrec_report(&unrec, UNREC_REPORT_DUMP, dump_line, NULL);
    }
    unrec_finish(&unrec);
    fflush(stdout);
    return status;
}
