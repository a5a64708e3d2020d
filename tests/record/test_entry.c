/* test_entry.c: every generated entry point, against the stub GL.
 *
 * For each AUTO and PRIM row of format/commands.def the test calls the
 * raygl twin with deterministic values and checks that (1) the real
 * function was called once with the same arguments, (2) the bytes recorded
 * equal what rgl_cmd_encode() makes of the same values, and (3) they decode
 * back to those values. The hand-written entry points (test_custom.c) and
 * the failure paths (allocation failure at the Nth allocation) follow.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "raygl.h"
#include "recorder.h"
#include "stubgl.h"

void test_custom(const char *dir);
void test_buffers(const char *dir);
void test_eval(const char *dir);
void test_nurbs_rec(const char *dir);
void test_select(const char *dir);
void test_multitex_arrays(const char *dir);
void test_alloc_failures(const char *dir);
void test_buffer_reuse(const char *dir);
void test_too_large(const char *dir);
void test_unpack(const char *dir);
void test_pixel_rules(const char *dir);
void test_raster(const char *dir);
void test_texcopy_nocontext(const char *dir);
void test_pbo(const char *dir);
void test_live_bindings(const char *dir);
void test_reopen(const char *dir);
void test_buffer_rules(const char *dir);
void test_fogsec_arrays(const char *dir);
void test_snaptex_support(const char *dir);
void test_pstipple(const char *dir);
void test_pstipple_snapshot(const char *dir);

/* ---- Deterministic values ------------------------------------------------------- */

static uint32_t mix(uint32_t op, const char *name, uint32_t k)
{
    uint32_t h = 2166136261u ^ op * 16777619u;
    for (const char *c = name; *c; c++)
        h = (h ^ (uint8_t)*c) * 16777619u;
    h = (h ^ k) * 16777619u;
    return h ^ (h >> 15);
}

/* The parameter name each handler's *v rows take: one with 4 values (3
 * for glPointParameter, whose largest is GL_POINT_DISTANCE_ATTENUATION). */
static uint32_t pname_for(const char *handler)
{
    if (!strcmp(handler, "light")) return GL_DIFFUSE;
    if (!strcmp(handler, "material")) return GL_SPECULAR;
    if (!strcmp(handler, "lightmodel")) return GL_LIGHT_MODEL_AMBIENT;
    if (!strcmp(handler, "fog")) return GL_FOG_COLOR;
    if (!strcmp(handler, "texenv")) return GL_TEXTURE_ENV_COLOR;
    if (!strcmp(handler, "texgen")) return GL_OBJECT_PLANE;
    if (!strcmp(handler, "pointparameter")) return GL_POINT_DISTANCE_ATTENUATION;
    return GL_AMBIENT;
}

/* A value of wire type t, exact in its C type, with negatives for the
 * signed types (zigzag) and multi-byte varints. */
static double value(int t, uint32_t op, const char *name, uint32_t k, const char *handler)
{
    uint32_t h = mix(op, name, k);
    switch (t) {
    case RGL_T_b: return (double)((int)(h % 201) - 100);
    case RGL_T_ub: return (double)(h % 256);
    case RGL_T_s: return (double)((int)(h % 60001) - 30000);
    case RGL_T_us: return (double)(h % 65536);
    case RGL_T_i: return (double)((int32_t)(h % 2000001) - 1000000);
    case RGL_T_ui: return (double)(h % 5000000);
    case RGL_T_f: return (double)((int)(h % 20001) - 10000) / 64.0;
    case RGL_T_d: return (double)((int)(h % 2000001) - 1000000) / 1024.0 + 1e-9;
    case RGL_T_e: return strcmp(name, "pname") == 0 ? pname_for(handler) : 0x1000 + h % 0x8000;
    case RGL_T_bf: return (double)(h % 0x100000);
    case RGL_T_bo: return (double)(h & 1);
    case RGL_T_sz: return (double)(h % 100000);
    default: return 0;
    }
}

static void set_scalar(rgl_arg *a, double v)
{
    switch (a->type) {
    case RGL_T_b: case RGL_T_s: case RGL_T_i: case RGL_T_sz: case RGL_T_ip:
        a->v.i = (int64_t)v;
        break;
    case RGL_T_f: case RGL_T_d:
        a->v.f = v;
        break;
    default:
        a->v.u = (uint64_t)v;
        break;
    }
}

static double *arg_array(rgl_cmd *cmd, unsigned i)
{
    return cmd->scratch + (cmd->arg[i].array - cmd->scratch);
}

/* ---- One row ---------------------------------------------------------------------- */

typedef struct row_check {
    rgl_cmd want;          /* the command as the test meant it */
    const char *realname;
    size_t before;         /* stream offset before the call */
    double scalars[RGL_MAX_ARGS];
    const void *ptrs[RGL_MAX_ARGS];
    unsigned nargs;
} row_check;

static size_t stream_offset(void)
{
    rgl_stream *s = rgl_tls_stream;
    return s ? (size_t)(s->pos - s->base) : 0;
}

static void row_begin(row_check *rc, uint32_t op, const char *realname)
{
    memset(rc, 0, sizeof *rc);
    CHECK(rgl_cmd_init(&rc->want, op) == RGL_OK);
    rc->realname = realname;
    stub_reset();
    rc->before = stream_offset();
}

static void row_end(row_check *rc)
{
    const char *name = rc->want.info->name;
    /* (1) The real function, once, with the same arguments. */
    CHECKM(stub_nlog == 1, "%s: %zu calls", name, stub_nlog);
    if (stub_nlog >= 1) {
        const stub_call *c = &stub_log[0];
        CHECKM(strcmp(c->name, rc->realname) == 0, "%s: called %s", name, c->name);
        CHECKM(c->nargs == rc->nargs, "%s: %u args", name, c->nargs);
        for (unsigned i = 0; i < rc->nargs && i < c->nargs; i++)
            CHECKM(c->v[i] == rc->scalars[i] && c->p[i] == rc->ptrs[i], "%s: arg %u", name, i);
    }
    /* (2) The bytes recorded are the encoder's. */
    rgl_stream *s = rgl_tls_stream;
    if (!CHECK(s != NULL))
        return;
    const uint8_t *got = s->base + rc->before;
    size_t got_n = (size_t)(s->pos - s->base) - rc->before;
    uint8_t enc[1024];
    size_t n = rgl_cmd_encode(&rc->want, enc, sizeof enc);
    CHECKM(n > 0, "%s: encode", name);
    CHECKM(n == got_n && memcmp(enc, got, n) == 0, "%s: recorded %zu bytes, encoder %zu", name,
           got_n, n);
    /* (3) They decode back to the values. */
    rgl_cmd_iter it;
    static rgl_cmd back;
    rgl_cmd_iter_init(&it, got, got_n, 0);
    if (!CHECKM(rgl_cmd_next(&it, &back) == RGL_OK, "%s: decode", name))
        return;
    CHECK(back.opcode == rc->want.opcode);
    CHECK(back.nargs == rc->want.nargs);
    for (unsigned i = 0; i < back.nargs && i < rc->want.nargs; i++) {
        const rgl_arg *a = &back.arg[i], *w = &rc->want.arg[i];
        CHECKM(a->count == w->count, "%s: arg %u count", name, i);
        for (uint32_t k = 0; k < a->count && k < w->count; k++)
            CHECKM(rgl_arg_f(a, k) == rgl_arg_f(w, k), "%s: arg %u[%u] %g != %g", name, i, k,
                   rgl_arg_f(a, k), rgl_arg_f(w, k));
    }
    CHECKM(rgl_cmd_next(&it, &back) == RGL_END, "%s: one command", name);
}

/* Declares each argument with its value, fills the expected command. */
#define TV_DECL_P(t, n)                                                        \
    RGL_CTYPE_##t n = (RGL_CTYPE_##t)value(RGL_T_##t, op_, #n, 0, handler_);   \
    set_scalar(&rc.want.arg[ai_], (double)n);                                  \
    rc.scalars[ai_] = (double)n;                                               \
    ai_++;
#define TV_DECL_A(t, n, c)                                                     \
    RGL_CTYPE_##t n[c];                                                        \
    for (uint32_t k_ = 0; k_ < (c); k_++) {                                    \
        n[k_] = (RGL_CTYPE_##t)value(RGL_T_##t, op_, #n, k_ + 1, handler_);    \
        arg_array(&rc.want, ai_)[k_] = (double)n[k_];                          \
    }                                                                          \
    rc.ptrs[ai_] = n;                                                          \
    ai_++;
#define TV_DECL_N(t, n, c)                                                     \
    RGL_CTYPE_##t n[RGL_ARRAY_MAX];                                            \
    {                                                                          \
        uint32_t cnt_ = (uint32_t)(c);                                         \
        CHECKM(cnt_ > 0 && cnt_ <= RGL_ARRAY_MAX, "%s count", #n);             \
        rc.want.arg[ai_].count = cnt_;                                         \
        for (uint32_t k_ = 0; k_ < RGL_ARRAY_MAX; k_++) {                      \
            n[k_] = (RGL_CTYPE_##t)value(RGL_T_##t, op_, #n, k_ + 1, handler_); \
            if (k_ < cnt_)                                                     \
                arg_array(&rc.want, ai_)[k_] = (double)n[k_];                  \
        }                                                                      \
    }                                                                          \
    rc.ptrs[ai_] = n;                                                          \
    ai_++;
#define TV_DECL_NOARGS

#define TV_ARG_P(t, n) n
#define TV_ARG_A(t, n, c) n
#define TV_ARG_N(t, n, c) n
#define TV_ARG_NOARGS

#define TV_GEN_AUTO(op, api, name, handler, ...)                               \
    static void row_##name(void)                                               \
    {                                                                          \
        const uint32_t op_ = op;                                               \
        const char *handler_ = #handler;                                       \
        row_check rc;                                                          \
        unsigned ai_ = 0;                                                      \
        (void)handler_;                                                        \
        row_begin(&rc, op_, RGL_NAMESTR(api, name));                           \
        RGL_MAP(TV_DECL_, __VA_ARGS__)                                         \
        rc.nargs = ai_;                                                        \
        RGL_APIFN(api, name)(RGL_MAP_LIST(TV_ARG_, __VA_ARGS__));              \
        row_end(&rc);                                                          \
    }
#define TV_GEN_PRIM TV_GEN_AUTO
#define TV_GEN_CUSTOM(op, api, name, handler, ...)
#define TV_GEN_WIRE(op, api, name, handler, ...)
#define RGL_CMD(op, api, gen, name, handler, ...) TV_GEN_##gen(op, api, name, handler, __VA_ARGS__)
#include "commands.def"
#undef RGL_CMD

static void (*const rows[])(void) = {
#define TV_LIST_AUTO(name) row_##name,
#define TV_LIST_PRIM(name) row_##name,
#define TV_LIST_CUSTOM(name)
#define TV_LIST_WIRE(name)
#define RGL_CMD(op, api, gen, name, handler, ...) TV_LIST_##gen(name)
#include "commands.def"
#undef RGL_CMD
};

/* A NULL pointer argument goes to GL (which reports or faults as it does)
 * but is not recorded. */
static void test_null_pointers(void)
{
    size_t before = stream_offset();
    stub_reset();
    rayglVertex3fv(NULL);
    rayglLightfv(GL_LIGHT0, GL_DIFFUSE, NULL);
    rayglLoadMatrixf(NULL);
    CHECK(stub_nlog == 3);
    CHECK(stream_offset() == before);
}

int main(void)
{
    char dir[] = "/tmp/raygl-entry-XXXXXX";
    if (!CHECK(mkdtemp(dir) != NULL))
        return check_exit();
    char path[128];
    snprintf(path, sizeof path, "%s/entry.raygl", dir);
    CHECK(rayglRecordOpen(path) == 0);
    rayglFlush(); /* opens the frame: no snapshot work inside the rows */
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++)
        rows[i]();
    CHECKM(sizeof rows / sizeof rows[0] > 200, "%zu rows", sizeof rows / sizeof rows[0]);
    test_null_pointers();
    rayglFrameEnd();
    rayglRecordClose();

    /* The trace holds that frame, whole, without a context. */
    rgl_reader *r = trace_open(path);
    if (r) {
        CHECK(rgl_reader_frame_count(r) == 1);
        rgl_frame_info fi;
        trace_cmds c = trace_frame(r, 0, &fi);
        CHECK(c.clean);
        CHECK(fi.flags == RGL_FRAME_STATE_CARRIED && fi.state == 0);
        CHECK(c.count == 2 + sizeof rows / sizeof rows[0]);
        trace_cmds_free(&c);
        rgl_reader_destroy(r);
    }
    unlink(path);

    test_custom(dir);
    test_buffers(dir);
    test_eval(dir);
    test_nurbs_rec(dir);
    test_select(dir);
    test_multitex_arrays(dir);
    test_alloc_failures(dir);
    test_buffer_reuse(dir);
    test_too_large(dir);
    test_unpack(dir);
    test_pixel_rules(dir);
    test_raster(dir);
    test_texcopy_nocontext(dir);
    test_pbo(dir);
    test_live_bindings(dir);
    test_reopen(dir);
    test_buffer_rules(dir);
    test_fogsec_arrays(dir);
    test_snaptex_support(dir);
    test_pstipple(dir);
    test_pstipple_snapshot(dir);
    if (!check_failures)
        rmdir(dir);
    return check_exit();
}
