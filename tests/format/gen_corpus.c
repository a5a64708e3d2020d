/* gen_corpus.c: writes the fuzz seed corpus (tests/format/corpus/).
 *
 * Usage: gen-corpus DIR. Small traces that between them hold every row of
 * the table with random valid arguments, with and without an index, with
 * command and byte resources, plus bare command sequences. Deterministic:
 * the same binary writes the same files. The files are checked in; rerun
 * this only to refresh them (and review the diff). The corpus also holds
 * recorded-*.bin, traces written by libraygl for the image tests.
 */
#include "testutil.h"

static uint8_t seq[1 << 16];

static size_t random_sequence(rng *r, size_t first_row, size_t rows, size_t *next_row)
{
    size_t nrows, len = 0;
    const rgl_cmd_info *const *all = rgl_cmd_info_all(&nrows);
    static rgl_cmd cmd;
    size_t i;
    for (i = first_row; i < nrows && i < first_row + rows; i++) {
        random_cmd(r, &cmd, all[i]->opcode);
        for (uint32_t k = 0; k < cmd.nargs; k++) {
            if (cmd.arg[k].kind == RGL_ARG_STRING || cmd.arg[k].kind == RGL_ARG_BLOB)
                cmd.arg[k].count = cmd.arg[k].count > 12 ? 12 : cmd.arg[k].count;
            if (cmd.arg[k].kind == RGL_ARG_COUNTED && cmd.arg[k].count > 4)
                cmd.arg[k].count = 4;
        }
        len += rgl_cmd_encode(&cmd, seq + len, sizeof seq - len);
    }
    if (next_row)
        *next_row = i;
    return len;
}

static int write_file(const char *dir, const char *name, const uint8_t *data, size_t size)
{
    char path[1024];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "wb");
    if (!f || fwrite(data, 1, size, f) != size) {
        fprintf(stderr, "gen-corpus: cannot write %s\n", path);
        if (f)
            fclose(f);
        return 1;
    }
    fclose(f);
    return 0;
}

static int write_trace(rng *r, const char *dir, const char *name, bool with_index,
                       size_t rows_per_frame)
{
    static const char info[] = "program=gen-corpus\nrecorder=raygl test\n";
    static const uint8_t texels[] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 9, 9, 9, 9};
    rgl_trace_builder *b = rgl_trace_builder_create();
    const uint8_t *data;
    size_t size, nrows, row = 0, len;
    uint32_t snap = 0, tex = 0, frame = 0;
    int rc = 1;

    rgl_cmd_info_all(&nrows);
    if (!b)
        return 1;
    rgl_trace_builder_info(b, info, sizeof info - 1);
    len = random_sequence(r, 0, 6, NULL);
    rgl_trace_builder_resource(b, RGL_RES_COMMANDS, seq, len, &snap);
    rgl_trace_builder_resource(b, RGL_RES_BYTES, texels, sizeof texels, &tex);
    while (row < nrows) {
        len = random_sequence(r, row, rows_per_frame, &row);
        if (rgl_trace_builder_frame(b, frame % 2, frame, frame % 2 ? RGL_FRAME_STATE_CARRIED : 0,
                                    frame % 2 ? 0 : snap, seq, len) != RGL_OK)
            goto out;
        frame++;
    }
    if (rgl_trace_builder_finish(b, with_index, &data, &size) == RGL_OK)
        rc = write_file(dir, name, data, size);
out:
    rgl_trace_builder_destroy(b);
    return rc;
}

int main(int argc, char **argv)
{
    rng r = {0x5eed5eed12345678ull};
    size_t nrows, row = 0, len;
    char name[64];
    int rc = 0;

    if (argc != 2) {
        fprintf(stderr, "usage: gen-corpus DIR\n");
        return 2;
    }
    rgl_cmd_info_all(&nrows);
    rc |= write_trace(&r, argv[1], "trace-index.bin", true, 64);
    rc |= write_trace(&r, argv[1], "trace-noindex.bin", false, 64);
    rc |= write_trace(&r, argv[1], "trace-small.bin", true, 256);
    /* Bare command sequences, a slice of the table each. */
    for (int k = 0; row < nrows; k++) {
        len = random_sequence(&r, row, 32, &row);
        snprintf(name, sizeof name, "seq-%02d.bin", k);
        rc |= write_file(argv[1], name, seq, len);
    }
    return rc;
}
