/* test_tables.c: the tables derived from commands.def, pnames.def and
 * enums.def. Every row is reachable by its opcode and sane; hot per-vertex
 * calls have one-byte opcodes; status strings are distinct; and every enum
 * and pname value written by hand in format/ matches the system's
 * <GL/gl.h> and <GL/glu.h> (format/ itself has no GL header).
 */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glu.h>

#include "testutil.h"

static void test_rows(void)
{
    size_t n, hot = 0;
    const rgl_cmd_info *const *all = rgl_cmd_info_all(&n);
    CHECK(n > 200);
    for (size_t i = 0; i < n; i++) {
        const rgl_cmd_info *c = all[i];
        CHECKF(rgl_cmd_info_get(c->opcode) == c, "row %s not found by its opcode", c->name);
        CHECK(c->opcode > 0 && c->opcode < RGL_OPCODE_LIMIT);
        CHECK(c->nargs <= RGL_MAX_ARGS);
        CHECK(c->name && c->handler && c->handler[0]);
        for (size_t j = 0; j < i; j++)
            CHECKF(strcmp(all[j]->name, c->name) != 0, "duplicate name %s", c->name);
        for (uint32_t k = 0; k < c->nargs; k++) {
            const rgl_arg_desc *d = &c->args[k];
            CHECK(d->name && d->name[0]);
            CHECK(d->type < RGL_T_COUNT);
            if (d->kind == RGL_ARG_ARRAY)
                CHECK(d->count >= 1 && d->count <= RGL_ARRAY_MAX);
        }
        /* Per-vertex calls must stay one byte on the wire. */
        if (!strcmp(c->handler, "vertex") || !strcmp(c->handler, "normal") ||
            !strcmp(c->handler, "color") || !strcmp(c->handler, "texcoord")) {
            CHECKF(c->opcode < 0x80, "%s has a two-byte opcode", c->name);
            hot++;
        }
    }
    CHECK(rgl_cmd_info_get(0) == NULL);
    CHECK(rgl_cmd_info_get(RGL_OPCODE_LIMIT) == NULL);
    CHECK(rgl_cmd_info_get(UINT32_MAX) == NULL);
    CHECK(rgl_cmd_info_get(RGL_OP_Vertex3f) && !strcmp(rgl_cmd_info_get(RGL_OP_Vertex3f)->name,
                                                         "glVertex3f"));
    CHECK(!strcmp(rgl_cmd_info_get(RGL_OP_Matrix)->name, "@Matrix"));
    CHECK(!strcmp(rgl_cmd_info_get(RGL_OP_Sphere)->name, "gluSphere"));
    CHECK(!strcmp(rgl_cmd_info_get(RGL_OP_SolidTeapot)->name, "glutSolidTeapot"));
    CHECK(!strcmp(rgl_cmd_info_get(RGL_OP_FrameBegin)->name, "rayglFrameBegin"));
    CHECK(rgl_cmd_info_get(RGL_OP_Lightfv)->nargs == 3 &&
          rgl_cmd_info_get(RGL_OP_Lightfv)->args[2].kind == RGL_ARG_COUNTED);
    printf("  %zu rows: found by opcode, unique names, sane descriptors, %zu hot rows < 0x80\n",
           n, hot);
}

static void test_status(void)
{
    for (int i = 0; i < RGL_STATUS_COUNT; i++) {
        CHECK(rgl_status_str((rgl_status)i) != NULL);
        for (int j = 0; j < i; j++)
            CHECK(strcmp(rgl_status_str((rgl_status)i), rgl_status_str((rgl_status)j)) != 0);
    }
    CHECK(rgl_status_str(RGL_STATUS_COUNT) != NULL);
    CHECK(rgl_status_str((rgl_status)-1) != NULL);
    printf("  %d status strings, distinct, never NULL\n", RGL_STATUS_COUNT);
}

static void test_pnames(void)
{
    int rows = 0;
#define RGL_PNAME(name, value, count, families)                                       \
    CHECKF((value) == (name), #name " is 0x%x in pnames.def, 0x%x in GL", (value), (name)); \
    CHECK(rgl_pname_count(name) == (count));                                          \
    CHECK(rgl_pname_count_in(families, name) == (count));                             \
    CHECK(rgl_pname_count_in(~(uint32_t)(families), name) == 0);                      \
    rows++;
#include "pnames.def"
#undef RGL_PNAME
    CHECK(rgl_pname_count(GL_AMBIENT) == 4 && rgl_pname_count(GL_SPOT_DIRECTION) == 3);
    CHECK(rgl_pname_count(GL_SHININESS) == 1 && rgl_pname_count(GL_FOG_COLOR) == 4);
    CHECK(rgl_pname_count(GL_EYE_PLANE) == 4 && rgl_pname_count(GL_TEXTURE_ENV_MODE) == 1);
    CHECK(rgl_pname_count(0) == 0 && rgl_pname_count(GL_LIGHT0) == 0);
    /* A name of another call: GL refuses it, nothing is read. */
    CHECK(rgl_pname_count_in(RGL_PN_FOG, GL_AMBIENT) == 0);
    CHECK(rgl_pname_count_in(RGL_PN_MATERIAL, GL_AMBIENT) == 4);
    CHECK(rgl_pname_count_in(RGL_PN_LIGHT, GL_SHININESS) == 0);
    CHECK(rgl_pname_count_in(RGL_PN_TEX_ENV, GL_TEXTURE_BORDER_COLOR) == 0);
    printf("  %d pname rows match <GL/gl.h>; counts as the GL spec says\n", rows);
}

static void test_enums(void)
{
    int rows = 0;
#define RGL_ENUM(family, name, value)                                                 \
    CHECKF((uint32_t)(value) == (uint32_t)(name), #name " is 0x%x in enums.def, 0x%x in GL", \
           (unsigned)(value), (unsigned)(name));                                      \
    rows++;
#include "enums.def"
#undef RGL_ENUM

    static const struct {
        uint32_t value;
        const char *hint, *name;
    } cases[] = {
        {0, "mode", "GL_POINTS"},       {4, "mode", "GL_TRIANGLES"},
        {9, "mode", "GL_POLYGON"},      {0, "sfactor", "GL_ZERO"},
        {1, "dfactor", "GL_ONE"},       {0x302, "sfactor", "GL_SRC_ALPHA"},
        {0x302, NULL, "GL_SRC_ALPHA"},  {0, "cap", NULL},
        {1, NULL, NULL},                {4, "count", NULL},
        {0x4000, "light", "GL_LIGHT0"}, {0x1203, "pname", "GL_POSITION"},
        {0x1D00, "mode", "GL_FLAT"},    {0x1700, "mode", "GL_MODELVIEW"},
        {0x1B01, "mode", "GL_LINE"},    {0x1300, "mode", "GL_COMPILE"},
        {0x0DE1, "cap", "GL_TEXTURE_2D"}, {0x1403, "type", "GL_UNSIGNED_SHORT"},
        {100012, "draw", "GLU_FILL"},   {100020, "orientation", "GLU_OUTSIDE"},
        {100000, "normal", "GLU_SMOOTH"}, {0x2A27, "format", "GL_T2F_V3F"},
        {1, "flag", "GL_TRUE"},         {0xdeadbeef, "mode", NULL},
        {0x12345, NULL, NULL},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *got = rgl_enum_name(cases[i].value, cases[i].hint);
        CHECKF(got == cases[i].name || (got && cases[i].name && !strcmp(got, cases[i].name)),
               "rgl_enum_name(0x%x, %s) = %s, want %s", (unsigned)cases[i].value,
               cases[i].hint ? cases[i].hint : "NULL", got ? got : "NULL",
               cases[i].name ? cases[i].name : "NULL");
    }
    printf("  %d enum rows match <GL/gl.h> and <GL/glu.h>; hints resolve shared values\n", rows);
}

int main(void)
{
    test_rows();
    test_status();
    test_pnames();
    test_enums();
    return test_summary("test_tables");
}
