/* tables.c: everything derived from the format's tables.
 *
 * The status strings, the command rows of commands.def (descriptors, the
 * opcode lookup, table order), the pname value counts of pnames.def and the
 * enum names of enums.def; plus the one allocation wrapper of format/. The
 * opcode and pname lookups are switches generated from their tables: a
 * duplicate opcode or pname value is a duplicate case label, which does not
 * compile.
 */
#include <stdlib.h>
#include <string.h>

#include "format.h"

/* The table this file expands. Only tests/format overrides it, to show that a
 * table with a duplicate opcode does not compile. */
#ifndef RGL_COMMANDS_DEF
#define RGL_COMMANDS_DEF "commands.def"
#endif

/* ---- Status strings ------------------------------------------------------- */

static const char *const status_strings[RGL_STATUS_COUNT] = {
    [RGL_OK] = "success",
    [RGL_END] = "end of sequence",
    [RGL_E_TRUNCATED] = "input truncated",
    [RGL_E_MAGIC] = "not a RayGL trace",
    [RGL_E_VERSION] = "unsupported format version",
    [RGL_E_BYTE_ORDER] = "byte order or float layout mismatch",
    [RGL_E_CHECKSUM] = "checksum mismatch",
    [RGL_E_CHUNK] = "malformed chunk header",
    [RGL_E_OPCODE] = "unknown opcode",
    [RGL_E_VARINT] = "malformed varint",
    [RGL_E_LIMIT] = "count or length over its limit",
    [RGL_E_RESOURCE] = "missing or malformed resource",
    [RGL_E_NOMEM] = "out of memory",
    [RGL_E_IO] = "I/O error",
    [RGL_E_STATE] = "call not allowed in this state",
    [RGL_E_ARGUMENT] = "bad argument",
    [RGL_E_IMAGE] = "malformed snapshot image",
};

const char *rgl_status_str(rgl_status status)
{
    if ((unsigned)status >= RGL_STATUS_COUNT || !status_strings[status])
        return "unknown status";
    return status_strings[status];
}

/* ---- Command rows ----------------------------------------------------------- */

/* Descriptor arrays, one per row; the trailing zero row keeps NOARGS rows
 * from being empty arrays (nargs comes from RGL_COUNT_, not the length). */
#define RGL_CMD(op, api, gen, name, handler, ...)                                   \
    static const rgl_arg_desc args_##name[] = {RGL_MAP(RGL_DESC_, __VA_ARGS__){      \
        RGL_ARG_SCALAR, 0, 0, NULL}};
#include RGL_COMMANDS_DEF
#undef RGL_CMD

#define RGL_CMD(op, api, gen, name, handler, ...)                                   \
    _Static_assert((op) > 0 && (op) < RGL_OPCODE_LIMIT, "opcode out of range: " #name); \
    _Static_assert((0 RGL_MAP(RGL_COUNT_, __VA_ARGS__)) <= RGL_MAX_ARGS,              \
                   "too many arguments: " #name);                                   \
    static const rgl_cmd_info info_##name = {                                       \
        op, RGL_API_##api, 0 RGL_MAP(RGL_COUNT_, __VA_ARGS__), RGL_NAMESTR(api, name), \
        #handler, args_##name};
#include RGL_COMMANDS_DEF
#undef RGL_CMD

static const rgl_cmd_info *const all_rows[] = {
#define RGL_CMD(op, api, gen, name, handler, ...) &info_##name,
#include RGL_COMMANDS_DEF
#undef RGL_CMD
};

/* A switch rather than a hand-filled array: duplicate case labels are a hard
 * error, so two rows with one opcode cannot build. Dense as the opcodes are,
 * the compiler emits it as an array indexed by opcode. */
const rgl_cmd_info *rgl_cmd_info_get(uint32_t opcode)
{
    switch (opcode) {
#define RGL_CMD(op, api, gen, name, handler, ...)                                   \
    case op:                                                                        \
        return &info_##name;
#include RGL_COMMANDS_DEF
#undef RGL_CMD
    default:
        return NULL;
    }
}

/* Per argument: 4 for a float scalar, past any row's size for the others. */
#define RGL_FSZ_P(t, n) +RGL_FSZ_T_##t
#define RGL_FSZ_A(t, n, cnt) +1000
#define RGL_FSZ_N(t, n, cnt) +1000
#define RGL_FSZ_BLOB(n) +1000
#define RGL_FSZ_STR(n) +1000
#define RGL_FSZ_NOARGS +1000
#define RGL_FSZ_T_f 4
#define RGL_FSZ_T_b 1000
#define RGL_FSZ_T_ub 1000
#define RGL_FSZ_T_s 1000
#define RGL_FSZ_T_us 1000
#define RGL_FSZ_T_i 1000
#define RGL_FSZ_T_sz 1000
#define RGL_FSZ_T_ui 1000
#define RGL_FSZ_T_e 1000
#define RGL_FSZ_T_bf 1000
#define RGL_FSZ_T_h 1000
#define RGL_FSZ_T_d 1000
#define RGL_FSZ_T_bo 1000
#define RGL_FSZ_T_ip 1000
#define RGL_FSZ_API_GL 1
#define RGL_FSZ_API_GLU 1
#define RGL_FSZ_API_GLUT 1
#define RGL_FSZ_API_RAY 1
#define RGL_FSZ_API_REC 0

/* Constant cases: the compiler turns the switch into a table. */
uint32_t rgl_cmd_float_size(uint32_t opcode)
{
    switch (opcode) {
#define RGL_CMD(op, api, gen, name, handler, ...)                                   \
    case op:                                                                        \
        return RGL_FSZ_API_##api && (op) < 0x80 &&                                  \
                       (0 RGL_MAP(RGL_FSZ_, __VA_ARGS__)) < 1000                    \
                   ? 1 + (0 RGL_MAP(RGL_FSZ_, __VA_ARGS__))                         \
                   : 0;
#include RGL_COMMANDS_DEF
#undef RGL_CMD
    default:
        return 0;
    }
}

const rgl_cmd_info *const *rgl_cmd_info_all(size_t *count)
{
    if (count)
        *count = sizeof all_rows / sizeof all_rows[0];
    return all_rows;
}

/* ---- Parameter counts ----------------------------------------------------------- */

uint32_t rgl_pname_count(uint32_t pname)
{
    switch (pname) {
#define RGL_PNAME(name, value, count, families)                                      \
    case value:                                                                     \
        return count;
#include "pnames.def"
#undef RGL_PNAME
    default:
        return 0;
    }
}

/* GL_MAP1_COLOR_4 (0x0D90) .. GL_MAP1_VERTEX_4 (0x0D98) and GL_MAP2_* at
 * 0x0DB0 in the same order: COLOR_4, INDEX, NORMAL, TEXTURE_COORD_1..4,
 * VERTEX_3, VERTEX_4. */
uint32_t rgl_map_components(uint32_t target, bool *two)
{
    static const uint8_t k[9] = {4, 1, 3, 1, 2, 3, 4, 3, 4};
    bool is2 = target >= 0x0DB0 && target <= 0x0DB8;
    if (two)
        *two = is2;
    if (target >= 0x0D90 && target <= 0x0D98)
        return k[target - 0x0D90];
    return is2 ? k[target - 0x0DB0] : 0;
}

uint32_t rgl_pname_count_in(uint32_t family, uint32_t pname)
{
    switch (pname) {
#define RGL_PNAME(name, value, count, families)                                      \
    case value:                                                                     \
        return ((families) & family) ? count : 0;
#include "pnames.def"
#undef RGL_PNAME
    default:
        return 0;
    }
}

/* ---- Enum names ------------------------------------------------------------------- */

enum enum_family { FAM_GEN, FAM_PRIM, FAM_BLEND, FAM_BOOL };

typedef struct enum_row {
    uint32_t value;
    uint8_t family;
    const char *name;
} enum_row;

static const enum_row enum_rows[] = {
#define RGL_ENUM(family, name, value) {value, FAM_##family, #name},
#include "enums.def"
#undef RGL_ENUM
};

/* Argument names that pick a family for the shared small values. */
static const struct {
    const char *hint;
    uint8_t family;
} enum_hints[] = {
    {"mode", FAM_PRIM}, /* glBegin, glDrawArrays, glDrawElements, ... */
    {"sfactor", FAM_BLEND},
    {"dfactor", FAM_BLEND},
    {"flag", FAM_BOOL},
};

/* Below this a value is shared by too many names (primitive modes, blend
 * factors, booleans, counts) to be named without a family. */
#define ENUM_SMALL 0x100u

const char *rgl_enum_name(uint32_t value, const char *hint)
{
    size_t nrows = sizeof enum_rows / sizeof enum_rows[0];
    if (hint) {
        for (size_t h = 0; h < sizeof enum_hints / sizeof enum_hints[0]; h++) {
            if (strcmp(hint, enum_hints[h].hint) != 0)
                continue;
            for (size_t i = 0; i < nrows; i++)
                if (enum_rows[i].value == value && enum_rows[i].family == enum_hints[h].family)
                    return enum_rows[i].name;
            break;
        }
    }
    if (value < ENUM_SMALL)
        return NULL;
    for (size_t i = 0; i < nrows; i++)
        if (enum_rows[i].value == value)
            return enum_rows[i].name;
    return NULL;
}

/* ---- Allocation --------------------------------------------------------------------- */

static unsigned long alloc_fail_at; /* 0: never; else countdown to the failing call */

void rgl_format_fail_alloc(unsigned long n) { alloc_fail_at = n; }

void *rgl_format_realloc(void *ptr, size_t size)
{
    if (size == 0) {
        free(ptr);
        return NULL;
    }
    if (alloc_fail_at) {
        if (alloc_fail_at == 1)
            return NULL; /* stays at 1: every later allocation fails too */
        alloc_fail_at--;
    }
    return realloc(ptr, size);
}
