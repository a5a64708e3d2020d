/* test_spec.c: docs/format.md's command table matches commands.def.
 *
 * The spec lists every opcode with its name and wire arguments, so a reader
 * can be written from the spec alone; this test regenerates that listing
 * from the table and compares it with the text between the markers in the
 * spec. Usage: test-format-spec SPEC.md (compare) or test-format-spec
 * --print (write the listing, to paste into the spec when rows are added).
 */
#include <ctype.h>

#include "testutil.h"

static const char *const type_names[RGL_T_COUNT] = {
    "b", "ub", "s", "us", "i", "ui", "f", "d", "e", "bf", "bo", "sz", "h", "ip"};

static size_t listing(char *out, size_t cap)
{
    size_t n = 0, rows;
    const rgl_cmd_info *const *all = rgl_cmd_info_all(&rows);
#define OUT(...) n += (size_t)snprintf(out + n, n < cap ? cap - n : 0, __VA_ARGS__)
    OUT("| opcode | name | arguments, in wire order |\n");
    OUT("|---|---|---|\n");
    for (size_t i = 0; i < rows; i++) {
        const rgl_cmd_info *c = all[i];
        OUT("| 0x%03x | %s | ", c->opcode, c->name);
        for (uint32_t k = 0; k < c->nargs; k++) {
            const rgl_arg_desc *d = &c->args[k];
            if (k)
                OUT(", ");
            switch (d->kind) {
            case RGL_ARG_SCALAR: OUT("%s %s", type_names[d->type], d->name); break;
            case RGL_ARG_ARRAY: OUT("%s %s[%u]", type_names[d->type], d->name, d->count); break;
            case RGL_ARG_COUNTED: OUT("%s %s[n]", type_names[d->type], d->name); break;
            case RGL_ARG_BLOB: OUT("BLOB %s", d->name); break;
            default: OUT("STR %s", d->name); break;
            }
        }
        if (!c->nargs)
            OUT("(none)");
        OUT(" |\n");
    }
#undef OUT
    return n;
}

/* The example of section 6, built with the library. */
static size_t example(const uint8_t **data, rgl_trace_builder **b)
{
    static uint8_t cmds[64];
    static rgl_cmd c;
    size_t n = 0, size = 0;
    rgl_cmd_init(&c, RGL_OP_Begin);
    c.arg[0].v.u = 4;
    n += rgl_cmd_encode(&c, cmds + n, sizeof cmds - n);
    rgl_cmd_init(&c, RGL_OP_Vertex3f);
    c.arg[0].v.f = 1;
    c.arg[1].v.f = 2;
    c.arg[2].v.f = -6;
    n += rgl_cmd_encode(&c, cmds + n, sizeof cmds - n);
    rgl_cmd_init(&c, RGL_OP_End);
    n += rgl_cmd_encode(&c, cmds + n, sizeof cmds - n);
    *b = rgl_trace_builder_create();
    rgl_trace_builder_info(*b, "program=demo\n", 13);
    rgl_trace_builder_frame(*b, 0, 0, 0, 0, cmds, n);
    rgl_trace_builder_finish(*b, true, data, &size);
    return size;
}

/* Parses the hex dump lines ("OFFSET  xx xx ...  note") after `from`. */
static size_t parse_dump(const char *from, uint8_t *out, size_t cap, bool *offsets_ok)
{
    size_t n = 0;
    const char *line = strstr(from, "```\n");
    *offsets_ok = true;
    if (!line)
        return 0;
    line += 4;
    while (*line && strncmp(line, "```", 3) != 0) {
        char *end;
        unsigned long off = strtoul(line, &end, 16);
        if (end - line == 8) {
            if (off != n)
                *offsets_ok = false;
            const char *p = end;
            while (p[0] == ' ' && p[1] == ' ' && p[2] != ' ')
                p += 2; /* the two spaces after the offset */
            for (;;) {
                while (*p == ' ' && p[1] != ' ')
                    p++;
                if (!isxdigit((unsigned char)p[0]) || !isxdigit((unsigned char)p[1]) ||
                    (p[2] != ' ' && p[2] != '\n'))
                    break;
                if (n < cap)
                    out[n] = (uint8_t)strtoul((char[]){p[0], p[1], 0}, NULL, 16);
                n++;
                p += 2;
                if (*p == ' ' && p[1] == ' ')
                    break; /* the note starts */
            }
        }
        line = strchr(line, '\n');
        if (!line)
            break;
        line++;
    }
    return n;
}

int main(int argc, char **argv)
{
    static char want[1 << 17], doc[1 << 20];
    const char *begin_mark = "<!-- BEGIN COMMAND TABLE -->\n", *end_mark = "<!-- END COMMAND TABLE -->";
    size_t n = listing(want, sizeof want);

    CHECK(n < sizeof want);
    if (argc == 2 && !strcmp(argv[1], "--print")) {
        fwrite(want, 1, n, stdout);
        return 0;
    }
    if (argc != 2) {
        fprintf(stderr, "usage: test-format-spec SPEC.md | --print\n");
        return 2;
    }
    FILE *f = fopen(argv[1], "rb");
    size_t got = f ? fread(doc, 1, sizeof doc - 1, f) : 0;
    if (f)
        fclose(f);
    doc[got] = '\0';
    CHECKF(got > 0, "cannot read %s", argv[1]);
    char *b = strstr(doc, begin_mark), *e = b ? strstr(b, end_mark) : NULL;
    CHECKF(b && e, "markers not found in %s", argv[1]);
    if (b && e) {
        b += strlen(begin_mark);
        CHECKF((size_t)(e - b) == n && memcmp(b, want, n) == 0,
               "the command table in %s differs from commands.def; regenerate it with "
               "test-format-spec --print", argv[1]);
    }
    printf("  the spec's command table lists every row of commands.def as it is\n");

    const uint8_t *data;
    rgl_trace_builder *builder;
    size_t size = example(&data, &builder);
    static uint8_t dumped[4096];
    bool offsets_ok = false;
    const char *ex = strstr(doc, "## 6. Example");
    size_t dn = ex ? parse_dump(ex, dumped, sizeof dumped, &offsets_ok) : 0;
    CHECKF(ex && dn == size && memcmp(dumped, data, size) == 0,
           "the example bytes in the spec (%zu) are not what the library writes (%zu)", dn, size);
    CHECK(ex && offsets_ok);
    rgl_trace_builder_destroy(builder);
    printf("  the spec's example trace is byte for byte what the library writes\n");
    return test_summary("test_spec");
}
