/* fuzzgen.c: structure-aware generation and mutation of RayGL traces.
 *
 * Byte-level fuzzing rarely gets a whole command past the framing, and never
 * builds what makes the translator work hard: display lists whose bodies
 * (COMMANDS resources) call other lists or themselves, array draws with
 * their @ArrayData, textures with their BYTES resources, GLU and GLUT
 * shapes, frames that carry state. Here an input becomes a model (resources
 * in id order, frames in file order, each a byte sequence of whole
 * commands), is changed command by command, and is written back through
 * rgl_trace_builder with resource ids 1..n in model order.
 *
 * Every command comes from a row of format/commands.def through
 * rgl_cmd_info_all() and rgl_cmd_encode(); argument values come from the
 * row's descriptors (type and name), enums.def and pnames.def. The few
 * compositions (Begin/End, NewList with a body, a pointer with its
 * @ArrayData and a draw, a texture with its pixels) name their rows through
 * the RGL_OP_ constants, so a renamed row fails the build instead of going
 * stale.
 */
#include "fuzzgen.h"

#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "format.h"

/* ---- Randomness: splitmix64, seeded by the caller ---------------------------------------- */

typedef struct rng {
    uint64_t s;
} rng;

static uint64_t rnd(rng *r)
{
    uint64_t z = (r->s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static uint32_t below(rng *r, uint32_t n)
{
    return n ? (uint32_t)(rnd(r) % n) : 0;
}

/* True once in n. */
static bool one_in(rng *r, uint32_t n)
{
    return below(r, n) == 0;
}

/* ---- Growable bytes ------------------------------------------------------------------ */

typedef struct buf {
    uint8_t *p;
    size_t n, cap;
} buf;

/* A fuzzing tool: running out of memory here ends the run loudly. */
static void *xrealloc(void *p, size_t size)
{
    void *q = realloc(p, size ? size : 1);
    if (!q) {
        fprintf(stderr, "fuzzgen: out of memory\n");
        abort();
    }
    return q;
}

static void buf_reserve(buf *b, size_t extra)
{
    if (b->p && b->cap - b->n >= extra)
        return; /* never NULL after this: pointer arithmetic on NULL is undefined */
    size_t cap = b->cap ? b->cap : 64;
    while (cap - b->n < extra)
        cap *= 2;
    b->p = xrealloc(b->p, cap);
    b->cap = cap;
}

static void buf_insert(buf *b, size_t at, const void *d, size_t n)
{
    buf_reserve(b, n);
    memmove(b->p + at + n, b->p + at, b->n - at);
    if (n)
        memcpy(b->p + at, d, n);
    b->n += n;
}

static void buf_put(buf *b, const void *d, size_t n)
{
    buf_insert(b, b->n, d, n);
}

static void buf_erase(buf *b, size_t at, size_t n)
{
    memmove(b->p + at, b->p + at + n, b->n - at - n);
    b->n -= n;
}

static void buf_set(buf *b, const void *d, size_t n)
{
    b->n = 0;
    buf_put(b, d, n);
}

/* ---- The model ------------------------------------------------------------------------- */

#define FZ_MAX_RES 12
#define FZ_MAX_FRAMES 6
#define FZ_MAX_SPANS 4096

typedef struct fz_res {
    uint32_t kind;
    buf data;
} fz_res;

typedef struct fz_frame {
    uint32_t stream, number, flags, state;
    buf cmds;
} fz_frame;

typedef struct fz_trace {
    fz_res res[FZ_MAX_RES];
    size_t nres;
    fz_frame fr[FZ_MAX_FRAMES];
    size_t nfr;
    bool index;
} fz_trace;

static void trace_free(fz_trace *t)
{
    for (size_t i = 0; i < FZ_MAX_RES; i++)
        free(t->res[i].data.p);
    for (size_t i = 0; i < FZ_MAX_FRAMES; i++)
        free(t->fr[i].cmds.p);
    memset(t, 0, sizeof *t);
}

/* Where each whole command of a sequence starts and how long it is. */
typedef struct span {
    size_t off, len;
} span;

static rgl_cmd g_cmd; /* large: kept off the stack */

/* The spans of the valid prefix of b; the rest (bytes that do not decode)
 * is cut off when trim. Returns the count. */
static size_t seq_spans(buf *b, span *out, size_t max, bool trim)
{
    rgl_cmd_iter it;
    size_t n = 0, end = 0;
    rgl_cmd_iter_init(&it, b->p ? b->p : (const uint8_t *)"", b->n, 0);
    while (n < max && rgl_cmd_next(&it, &g_cmd) == RGL_OK) {
        size_t next = (size_t)(it.pos - it.start);
        out[n].off = end;
        out[n].len = next - end;
        end = next;
        n++;
    }
    if (trim)
        b->n = end;
    return n;
}

/* ---- Reading an input into the model -------------------------------------------------- */

static void trace_from_bytes(fz_trace *t, const uint8_t *data, size_t size)
{
    static span sp[FZ_MAX_SPANS];
    rgl_reader *r = NULL;

    memset(t, 0, sizeof *t);
    t->index = true;
    if (size >= RGL_FILE_MAGIC_SIZE && memcmp(data, RGL_FILE_MAGIC, RGL_FILE_MAGIC_SIZE) == 0 &&
        rgl_reader_open_memory(data, size, &r, NULL) == RGL_OK) {
        for (size_t i = 0; i < rgl_reader_resource_count(r) && t->nres < FZ_MAX_RES; i++) {
            rgl_resource res;
            if (rgl_reader_resource_at(r, i, &res, NULL) != RGL_OK)
                continue;
            fz_res *x = &t->res[t->nres++];
            x->kind = res.kind;
            buf_set(&x->data, res.data, res.size);
        }
        for (size_t i = 0; i < rgl_reader_frame_count(r) && t->nfr < FZ_MAX_FRAMES; i++) {
            rgl_frame_info f;
            if (rgl_reader_frame(r, i, &f, NULL) != RGL_OK)
                continue;
            fz_frame *x = &t->fr[t->nfr++];
            x->stream = f.stream;
            x->number = f.number;
            x->flags = f.flags;
            x->state = f.state;
            buf_set(&x->cmds, f.commands, f.commands_size);
        }
        rgl_reader_destroy(r);
        return;
    }
    /* Bare commands: from byte 0 (the decode target) or byte 1 (the
     * translate target's flag byte), whichever decodes further. */
    buf a = {0}, b = {0};
    buf_set(&a, data, size);
    if (size)
        buf_set(&b, data + 1, size - 1);
    size_t na = seq_spans(&a, sp, FZ_MAX_SPANS, true);
    size_t nb = seq_spans(&b, sp, FZ_MAX_SPANS, true);
    fz_frame *x = &t->fr[t->nfr++];
    if (nb > na) {
        x->cmds = b;
        free(a.p);
    } else {
        x->cmds = a;
        free(b.p);
    }
}

static size_t trace_to_bytes(const fz_trace *t, uint8_t *out, size_t max_size)
{
    rgl_trace_builder *b = rgl_trace_builder_create();
    const uint8_t *data;
    size_t size = 0;
    uint32_t id;
    static const uint8_t none[1];

    if (!b)
        return 0;
    for (size_t i = 0; i < t->nres; i++)
        if (rgl_trace_builder_resource(b, t->res[i].kind,
                                       t->res[i].data.n ? t->res[i].data.p : none,
                                       t->res[i].data.n, &id) != RGL_OK)
            goto out;
    for (size_t i = 0; i < t->nfr; i++) {
        const fz_frame *f = &t->fr[i];
        if (rgl_trace_builder_frame(b, f->stream, f->number, f->flags, f->state,
                                    f->cmds.n ? f->cmds.p : none, f->cmds.n) != RGL_OK)
            goto out;
    }
    if (rgl_trace_builder_finish(b, t->index, &data, &size) != RGL_OK || size > max_size) {
        size = 0;
        goto out;
    }
    memcpy(out, data, size);
out:
    rgl_trace_builder_destroy(b);
    return size;
}

/* ---- Values from the tables ------------------------------------------------------------- */

enum { FAM_GEN, FAM_PRIM, FAM_BLEND, FAM_BOOL };

static const struct {
    uint8_t family;
    uint32_t value;
} enums[] = {
#define RGL_ENUM(family, name, value) {FAM_##family, value},
#include "enums.def"
#undef RGL_ENUM
};
#define N_ENUMS (sizeof enums / sizeof enums[0])

static const uint32_t pnames[] = {
#define RGL_PNAME(name, value, count, families) value,
#include "pnames.def"
#undef RGL_PNAME
};
#define N_PNAMES (sizeof pnames / sizeof pnames[0])

/* Rows sorted into the roles the compositions need, once, from the table. */
static struct {
    bool ready;
    const rgl_cmd_info *const *all;
    size_t nall;
    const rgl_cmd_info *vertex[64], *attrib[128], *shape[48], *xform[48];
    size_t nvertex, nattrib, nshape, nxform;
} rows;

static bool starts(const char *s, const char *prefix)
{
    return strncmp(s, prefix, strlen(prefix)) == 0;
}

static void rows_init(void)
{
    if (rows.ready)
        return;
    rows.all = rgl_cmd_info_all(&rows.nall);
    for (size_t i = 0; i < rows.nall; i++) {
        const rgl_cmd_info *c = rows.all[i];
        const char *h = c->handler;
        if (!strcmp(h, "vertex") && rows.nvertex < 64)
            rows.vertex[rows.nvertex++] = c;
        else if ((!strcmp(h, "color") || !strcmp(h, "normal") || !strcmp(h, "texcoord") ||
                  !strcmp(h, "edgeflag") || !strcmp(h, "material")) &&
                 rows.nattrib < 128)
            rows.attrib[rows.nattrib++] = c;
        /* GLUT solids and GLU quadric shapes: handlers glut* and glu*,
         * minus the quadric's own bookkeeping rows */
        else if ((starts(h, "glut") || (starts(h, "glu") && c->nargs > 1 &&
                                        !starts(h, "quadric"))) &&
                 rows.nshape < 48)
            rows.shape[rows.nshape++] = c;
        else if ((!strcmp(h, "translate") || !strcmp(h, "rotate") || !strcmp(h, "scale") ||
                  !strcmp(h, "multmatrix") || !strcmp(h, "loadmatrix") ||
                  !strcmp(h, "pushmatrix") || !strcmp(h, "popmatrix") ||
                  !strcmp(h, "loadidentity") || !strcmp(h, "multtransposematrix")) &&
                 rows.nxform < 48)
            rows.xform[rows.nxform++] = c;
    }
    rows.ready = true;
}

/* The generator's view of the trace being built or changed. */
typedef struct gen {
    rng r;
    fz_trace *t;
    uint32_t lists[16]; /* list names defined so far */
    size_t nlists;
} gen;

static double pick_double(gen *g, uint8_t type)
{
    static const double special[] = {0.0, 1.0, -1.0, 0.5, 2.0, 10.0, -10.0, 100.0, 1e-7,
                                     1e6, 1e30, -1e30, -0.0, 1e-40, 3.0e38, -3.0e38};
    rng *r = &g->r;
    switch (below(r, 8)) {
    case 0:
        return special[below(r, sizeof special / sizeof special[0])];
    case 1:
        if (one_in(r, 4))
            return one_in(r, 2) ? NAN : (one_in(r, 2) ? INFINITY : -INFINITY);
        return type == RGL_T_d ? (one_in(r, 2) ? DBL_MAX : 1e300) : FLT_MAX;
    default:
        return ((double)below(r, 2001) - 1000.0) / 100.0;
    }
}

static int64_t pick_int(gen *g)
{
    static const int64_t special[] = {0, 1, -1, 2, 3, 4, 7, 8, 16, 63, 64, 65, 127, 128, 255,
                                      256, 1000, 4096, 65535, 65536, 1 << 20, INT32_MAX,
                                      INT32_MIN, INT32_MAX - 1};
    rng *r = &g->r;
    if (one_in(r, 3))
        return special[below(r, sizeof special / sizeof special[0])];
    return (int64_t)below(r, 10);
}

static uint32_t pick_enum(gen *g, const rgl_cmd_info *c, const char *name)
{
    rng *r = &g->r;
    if (!strcmp(name, "pname") && !one_in(r, 8))
        return pnames[below(r, N_PNAMES)];
    if (!strcmp(name, "mode") && (!strcmp(c->handler, "begin") || starts(c->handler, "draw") ||
                                  starts(c->handler, "multidraw")) &&
        !one_in(r, 8)) {
        uint32_t k = below(r, N_ENUMS);
        while (enums[k].family != FAM_PRIM)
            k = (k + 1) % N_ENUMS;
        return enums[k].value;
    }
    if (one_in(r, 10))
        return (uint32_t)pick_int(g);
    return enums[below(r, N_ENUMS)].value;
}

/* A value for a ui or h scalar, by the argument's name. */
static uint64_t pick_name(gen *g, const char *name)
{
    rng *r = &g->r;
    if ((!strcmp(name, "list") || !strcmp(name, "base")) && g->nlists && !one_in(r, 4))
        return g->lists[below(r, (uint32_t)g->nlists)];
    if (!strcmp(name, "body") || !strcmp(name, "pixels") || !strcmp(name, "data") ||
        !strcmp(name, "image"))
        return below(r, (uint32_t)g->t->nres + 2);
    if (one_in(r, 6))
        return (uint32_t)pick_int(g);
    return below(r, 5);
}

/* One scalar for descriptor d of row c, stored as rgl_cmd_encode reads it. */
static void pick_scalar(gen *g, const rgl_cmd_info *c, const rgl_arg_desc *d, rgl_arg *a)
{
    rng *r = &g->r;
    int64_t v;
    switch (d->type) {
    case RGL_T_f:
    case RGL_T_d:
        a->v.f = pick_double(g, d->type);
        if (d->type == RGL_T_f && isfinite(a->v.f) && fabs(a->v.f) > FLT_MAX)
            a->v.f = FLT_MAX;
        break;
    case RGL_T_e:
        a->v.u = pick_enum(g, c, d->name);
        break;
    case RGL_T_bf:
        a->v.u = one_in(r, 2) ? 0x4100u : (one_in(r, 2) ? 0xffffffffu : below(r, 1u << 20));
        break;
    case RGL_T_bo:
    case RGL_T_ub:
        a->v.u = one_in(r, 2) ? below(r, 2) : below(r, 256);
        break;
    case RGL_T_us:
        a->v.u = one_in(r, 2) ? below(r, 4) : below(r, 65536);
        break;
    case RGL_T_b:
        a->v.i = (int64_t)below(r, 256) - 128;
        break;
    case RGL_T_s:
        a->v.i = one_in(r, 2) ? (int64_t)below(r, 9) - 4 : (int64_t)below(r, 65536) - 32768;
        break;
    case RGL_T_ui:
    case RGL_T_h:
        a->v.u = pick_name(g, d->name);
        break;
    default: /* i, sz, ip */
        v = pick_int(g);
        /* tessellations and sizes: mostly the sizes programs use */
        if (!one_in(r, 4) && (strstr(d->name, "slices") || strstr(d->name, "stacks") ||
                              !strcmp(d->name, "sides") || !strcmp(d->name, "rings") ||
                              !strcmp(d->name, "loops")))
            v = 3 + below(r, 30);
        a->v.i = v;
        break;
    }
}

static double pick_element(gen *g, uint8_t type)
{
    rng *r = &g->r;
    switch (type) {
    case RGL_T_f:
    case RGL_T_d: {
        double v = pick_double(g, type);
        return type == RGL_T_f && isfinite(v) && fabs(v) > FLT_MAX ? 1.0 : v;
    }
    case RGL_T_b:
        return (double)below(r, 256) - 128;
    case RGL_T_s:
        return (double)below(r, 65536) - 32768;
    case RGL_T_ub:
    case RGL_T_bo:
        return below(r, 256);
    case RGL_T_us:
        return below(r, 65536);
    case RGL_T_i:
    case RGL_T_sz:
        return (double)pick_int(g);
    default:
        return below(r, 8);
    }
}

static uint8_t g_bytes[1 << 14]; /* blob contents of the command being built */

/* Encodes row c with values picked for every argument into out. */
static size_t gen_cmd(gen *g, const rgl_cmd_info *c, uint8_t *out, size_t cap)
{
    rng *r = &g->r;
    uint32_t pname_count = 0;
    bool have_pname = false;
    size_t used = 0;

    if (rgl_cmd_init(&g_cmd, c->opcode) != RGL_OK)
        return 0;
    for (uint32_t i = 0; i < c->nargs; i++) {
        const rgl_arg_desc *d = &c->args[i];
        rgl_arg *a = &g_cmd.arg[i];
        switch (d->kind) {
        case RGL_ARG_SCALAR:
            pick_scalar(g, c, d, a);
            if (!strcmp(d->name, "pname")) {
                have_pname = true;
                pname_count = rgl_pname_count((uint32_t)a->v.u);
            }
            break;
        case RGL_ARG_ARRAY:
        case RGL_ARG_COUNTED:
            if (d->kind == RGL_ARG_COUNTED)
                a->count = have_pname && !one_in(r, 8) ? pname_count
                           : one_in(r, 8)              ? below(r, RGL_ARRAY_MAX + 1)
                                                       : below(r, 5);
            for (uint32_t k = 0; k < a->count; k++)
                ((double *)a->array)[k] = pick_element(g, d->type);
            break;
        case RGL_ARG_BLOB:
        case RGL_ARG_STRING: {
            uint32_t n = one_in(r, 8) ? below(r, 512) : below(r, 24);
            if (d->kind == RGL_ARG_STRING && one_in(r, 2)) {
                static const char *const names[] = {"f", "frame", "a\"b\\c\n", "%s%n",
                                                    "\xff\xfe", "x/../y", ""};
                const char *s = names[below(r, sizeof names / sizeof names[0])];
                n = (uint32_t)strlen(s);
                memcpy(g_bytes + used, s, n);
            } else {
                for (uint32_t k = 0; k < n; k++)
                    g_bytes[used + k] = one_in(r, 2) ? (uint8_t)below(r, 4) : (uint8_t)rnd(r);
            }
            a->bytes = g_bytes + used;
            a->count = n;
            used += n;
            break;
        }
        default:
            break;
        }
    }
    return rgl_cmd_encode(&g_cmd, out, cap);
}

static uint8_t g_enc[1 << 15]; /* one encoded command */

static void put_row(gen *g, buf *b, const rgl_cmd_info *c)
{
    size_t n = gen_cmd(g, c, g_enc, sizeof g_enc);
    if (n)
        buf_put(b, g_enc, n);
}

/* Appends opcode op with the given scalar values (the rest picked); bytes,
 * if given, fill the row's BLOB or STR argument. */
static void put_op(gen *g, buf *b, uint32_t op, const double *vals, size_t nvals,
                   const uint8_t *bytes, size_t nbytes)
{
    const rgl_cmd_info *c = rgl_cmd_info_get(op);
    if (!c || !gen_cmd(g, c, g_enc, sizeof g_enc))
        return;
    /* gen_cmd left g_cmd holding the picked values: override them */
    for (uint32_t i = 0, k = 0; i < c->nargs; i++) {
        rgl_arg *a = &g_cmd.arg[i];
        if (a->kind == RGL_ARG_SCALAR && k < nvals) {
            double v = vals[k++];
            if (a->type == RGL_T_f || a->type == RGL_T_d)
                a->v.f = v;
            else if (a->type == RGL_T_b || a->type == RGL_T_s || a->type == RGL_T_i ||
                     a->type == RGL_T_sz || a->type == RGL_T_ip)
                a->v.i = (int64_t)v;
            else
                a->v.u = (uint64_t)v;
        } else if ((a->kind == RGL_ARG_BLOB || a->kind == RGL_ARG_STRING) && bytes) {
            a->bytes = bytes;
            a->count = (uint32_t)nbytes;
        }
    }
    size_t n = rgl_cmd_encode(&g_cmd, g_enc, sizeof g_enc);
    if (n)
        buf_put(b, g_enc, n);
}

#define PUT(g, b, name, ...)                                                                  \
    put_op((g), (b), RGL_OP_##name, (const double[]){__VA_ARGS__},                            \
           sizeof((const double[]){__VA_ARGS__}) / sizeof(double), NULL, 0)

/* ---- Compositions --------------------------------------------------------------------- */

/* GL values the compositions use (GL 1.x spec, table 6.x; they never change) */
#define V_TRIANGLES 0x0004
#define V_COMPILE 0x1300
#define V_COMPILE_AND_EXECUTE 0x1301
#define V_UNSIGNED_BYTE 0x1401
#define V_UNSIGNED_SHORT 0x1403
#define V_UNSIGNED_INT 0x1405
#define V_FLOAT 0x1406
#define V_TEXTURE_2D 0x0DE1
#define V_RGB 0x1907
#define V_RGBA 0x1908
#define V_VERTEX_ARRAY 0x8074
#define V_LIGHTING 0x0B50
#define V_LIGHT0 0x4000
#define V_DEPTH_TEST 0x0B71

static void st_prim(gen *g, buf *b)
{
    rng *r = &g->r;
    uint32_t n = one_in(r, 6) ? below(r, 40) : 3 + below(r, 4);
    PUT(g, b, Begin, one_in(r, 3) ? V_TRIANGLES : pick_enum(g, rgl_cmd_info_get(RGL_OP_Begin), "mode"));
    for (uint32_t k = 0; k < n; k++) {
        if (rows.nattrib && one_in(r, 3))
            put_row(g, b, rows.attrib[below(r, (uint32_t)rows.nattrib)]);
        if (one_in(r, 2))
            PUT(g, b, Vertex3f, (double)below(r, 5) - 2, (double)below(r, 5) - 2,
                (double)below(r, 5) - 2);
        else if (rows.nvertex)
            put_row(g, b, rows.vertex[below(r, (uint32_t)rows.nvertex)]);
    }
    if (!one_in(r, 10))
        PUT(g, b, End, 0);
}

static void st_shape(gen *g, buf *b)
{
    rng *r = &g->r;
    if (!rows.nshape)
        return;
    const rgl_cmd_info *c = rows.shape[below(r, (uint32_t)rows.nshape)];
    if (c->nargs && !strcmp(c->args[0].name, "quad"))
        PUT(g, b, NewQuadric, 1);
    put_row(g, b, c);
}

/* A GLU NURBS surface or curve whose knots and points mostly fit their
 * sizes (random blobs almost never do), sometimes trimmed, in a display
 * mode picked at random. Each blob gets floats from g_bytes. */
static void put_nurbs(gen *g, buf *b, uint32_t op, const double *vals, size_t nvals,
                      const uint32_t *nfloats)
{
    rng *r = &g->r;
    if (rgl_cmd_init(&g_cmd, op) != RGL_OK)
        return;
    size_t used = 0, k = 0, nb = 0;
    for (uint32_t i = 0; i < g_cmd.nargs; i++) {
        rgl_arg *a = &g_cmd.arg[i];
        if (a->kind == RGL_ARG_BLOB) {
            uint32_t n = one_in(r, 16) ? below(r, 20) : nfloats[nb];
            float last = 0;
            for (uint32_t e = 0; e < n && used + 4 * e + 4 <= sizeof g_bytes; e++) {
                /* knots (the first blobs of a surface or curve) rise */
                float x = nb + 1 < (op == RGL_OP_NurbsSurface ? 3u : op == RGL_OP_NurbsCurve ? 2u : 0u)
                              ? (last += (float)below(r, 3) * 0.5f)
                              : (float)below(r, 9) * 0.25f - 1.0f;
                uint32_t bits;
                memcpy(&bits, &x, 4); /* little-endian IEEE-754 single */
                for (int c = 0; c < 4; c++)
                    g_bytes[used + 4 * e + (uint32_t)c] = (uint8_t)(bits >> (8 * c));
            }
            a->bytes = g_bytes + used;
            a->count = 4 * n;
            used += 4 * n;
            nb++;
        } else if (a->kind == RGL_ARG_SCALAR) {
            double v = k < nvals ? vals[k++] : 0;
            if (a->type == RGL_T_f)
                a->v.f = v;
            else if (a->type == RGL_T_i)
                a->v.i = (int64_t)v;
            else
                a->v.u = (uint64_t)v;
        }
    }
    size_t n = rgl_cmd_encode(&g_cmd, g_enc, sizeof g_enc);
    if (n)
        buf_put(b, g_enc, n);
}

static void st_nurbs(gen *g, buf *b)
{
    rng *r = &g->r;
    static const uint32_t modes[3] = {100012, 100240, 100241}; /* FILL, OUTLINE_POLYGON, _PATCH */
    PUT(g, b, NewNurbsRenderer, 1);
    if (one_in(r, 2))
        PUT(g, b, NurbsProperty, 1, 100204, modes[below(r, 3)]);
    if (one_in(r, 4))
        PUT(g, b, NurbsProperty, 1, 100205, 100217); /* GLU_DOMAIN_DISTANCE */
    if (one_in(r, 3)) {
        uint32_t order = 1 + below(r, 4), n = order + below(r, 4), type = one_in(r, 2) ? 0x0D98 : 0x0D97;
        uint32_t k = type == 0x0D98 ? 4 : 3;
        PUT(g, b, BeginCurve, 1);
        const uint32_t nf[2] = {n + order, n * k};
        put_nurbs(g, b, RGL_OP_NurbsCurve, (const double[]){1, n + order, k, order, type}, 5, nf);
        PUT(g, b, EndCurve, 1);
        return;
    }
    uint32_t so = 1 + below(r, 4), to = 1 + below(r, 4);
    uint32_t sn = so + below(r, 3), tn = to + below(r, 3);
    static const uint32_t types[4] = {0x0DB7, 0x0DB8, 0x0DB0, 0x0DB2}; /* V3, V4, COLOR_4, NORMAL */
    static const uint32_t kk[4] = {3, 4, 4, 3};
    PUT(g, b, BeginSurface, 1);
    for (uint32_t p = 0, np = 1 + below(r, 2); p < np; p++) {
        uint32_t t = p == 0 ? below(r, 2) : below(r, 4);
        const uint32_t nf[3] = {sn + so, tn + to, sn * tn * kk[t]};
        put_nurbs(g, b, RGL_OP_NurbsSurface,
                  (const double[]){1, sn + so, tn + to, kk[t] * tn, kk[t], so, to, types[t]}, 8, nf);
    }
    for (uint32_t l = 0, nl = below(r, 3); l < nl; l++) {
        uint32_t cnt = 3 + below(r, 4);
        PUT(g, b, BeginTrim, 1);
        const uint32_t nf[1] = {2 * cnt};
        put_nurbs(g, b, RGL_OP_PwlCurve, (const double[]){1, cnt, 2, 100210}, 4, nf);
        PUT(g, b, EndTrim, 1);
    }
    PUT(g, b, EndSurface, 1);
}

static void st_xform(gen *g, buf *b)
{
    rng *r = &g->r;
    if (rows.nxform)
        put_row(g, b, rows.xform[below(r, (uint32_t)rows.nxform)]);
}

static void st_draw(gen *g, buf *b, int depth);

/* A list body resource, then glNewList(name, mode, #body) and glEndList
 * where the recorder writes them. Bodies call lists already defined, the
 * list itself, or lists defined later: recursion and fan-out. */
static void st_list(gen *g, buf *b)
{
    rng *r = &g->r;
    fz_trace *t = g->t;
    uint32_t name = one_in(r, 4) || !g->nlists ? 1 + below(r, 4)
                                                : g->lists[below(r, (uint32_t)g->nlists)];
    if (t->nres >= FZ_MAX_RES)
        return;
    fz_res *res = &t->res[t->nres++];
    uint32_t id = (uint32_t)t->nres;
    res->kind = RGL_RES_COMMANDS;
    res->data.n = 0;
    if (g->nlists < 16)
        g->lists[g->nlists++] = name;
    uint32_t parts = 1 + below(r, 3);
    for (uint32_t k = 0; k < parts; k++)
        st_draw(g, &res->data, 1);
    /* mostly a call or none: two calls of itself already make 2^64 calls
     * under GL's nesting limit; the mutator's fan-out (case 13) grows more */
    uint32_t calls = one_in(r, 8) ? 2 + below(r, 2) : below(r, 2);
    for (uint32_t k = 0; k < calls; k++) {
        uint32_t callee = one_in(r, 4) ? name : g->lists[below(r, (uint32_t)g->nlists)];
        if (one_in(r, 4)) {
            uint8_t names[4] = {(uint8_t)callee, (uint8_t)name, 1, 2};
            double v[] = {4, V_UNSIGNED_BYTE};
            put_op(g, &res->data, RGL_OP_CallLists, v, 2, names, 4);
        } else {
            PUT(g, &res->data, CallList, callee);
        }
    }
    PUT(g, b, NewList, name, one_in(r, 3) ? V_COMPILE_AND_EXECUTE : V_COMPILE, id);
    PUT(g, b, EndList, 0);
    uint32_t uses = below(r, 3);
    for (uint32_t k = 0; k < uses; k++)
        PUT(g, b, CallList, g->lists[below(r, (uint32_t)g->nlists)]);
}

/* A vertex array: enable, pointer, the draw's @ArrayData, the draw. */
static void st_array(gen *g, buf *b)
{
    rng *r = &g->r;
    uint32_t count = one_in(r, 5) ? below(r, 64) : 3 + below(r, 6);
    uint32_t size = one_in(r, 6) ? below(r, 6) : 3;
    uint32_t first = one_in(r, 6) ? below(r, 4) : 0;
    static float v[64 * 5];
    for (uint32_t k = 0; k < 64 * 5; k++)
        v[k] = (float)below(r, 9) - 4.0f;
    size_t nbytes = (size_t)count * (size > 5 ? 5 : size) * sizeof(float);
    if (one_in(r, 8))
        nbytes = below(r, (uint32_t)nbytes + 8);
    uint8_t *bytes = g_bytes + 8192;
    memset(bytes, 0, nbytes);
    for (size_t k = 0; k < nbytes / 4; k++) {
        uint32_t u;
        memcpy(&u, &v[k], 4);
        for (int j = 0; j < 4; j++) /* little-endian on the wire */
            bytes[4 * k + (size_t)j] = (uint8_t)(u >> (8 * j));
    }
    PUT(g, b, EnableClientState, V_VERTEX_ARRAY);
    PUT(g, b, VertexPointer, size, V_FLOAT, 0);
    double ad[] = {V_VERTEX_ARRAY, first, size, V_FLOAT};
    put_op(g, b, RGL_OP_ArrayData, ad, 4, bytes, nbytes);
    if (one_in(r, 3)) { /* fog coordinates and secondary colours from the same bytes */
        double af[] = {0x8457 /* GL_FOG_COORD_ARRAY */, first, 1, V_FLOAT};
        double as[] = {0x845E /* GL_SECONDARY_COLOR_ARRAY */, first, 3, V_FLOAT};
        PUT(g, b, Enable, 0x8458); /* GL_COLOR_SUM */
        PUT(g, b, FogCoordPointer, V_FLOAT, 0);
        put_op(g, b, RGL_OP_ArrayData, af, 4, bytes, nbytes);
        put_op(g, b, RGL_OP_ArrayData, as, 4, bytes, nbytes);
    }
    if (one_in(r, 2)) {
        PUT(g, b, DrawArrays, one_in(r, 2) ? V_TRIANGLES : pick_enum(g, rgl_cmd_info_get(RGL_OP_DrawArrays), "mode"), first, count);
    } else {
        static const uint32_t types[] = {V_UNSIGNED_BYTE, V_UNSIGNED_SHORT, V_UNSIGNED_INT};
        uint32_t ti = below(r, 3), w = ti == 0 ? 1 : ti == 1 ? 2 : 4;
        uint8_t idx[256];
        uint32_t nidx = count > 64 ? 64 : count;
        for (uint32_t k = 0; k < nidx; k++) {
            uint32_t x = one_in(r, 10) ? (uint32_t)rnd(r) : below(r, count + 1);
            for (uint32_t j = 0; j < w; j++)
                idx[k * w + j] = (uint8_t)(x >> (8 * j));
        }
        double de[] = {V_TRIANGLES, nidx, types[ti]};
        put_op(g, b, RGL_OP_DrawElements, de, 3, idx, (size_t)nidx * w);
    }
    if (one_in(r, 2))
        PUT(g, b, DisableClientState, V_VERTEX_ARRAY);
}

/* A texture: its pixels as a BYTES resource, bound and enabled, then a
 * primitive with texture coordinates from the attribute rows. */
static void st_texture(gen *g, buf *b)
{
    rng *r = &g->r;
    fz_trace *t = g->t;
    if (t->nres >= FZ_MAX_RES)
        return;
    uint32_t w = one_in(r, 6) ? below(r, 70) : 1u << below(r, 4);
    uint32_t h = one_in(r, 6) ? below(r, 70) : 1u << below(r, 4);
    uint32_t fmt = one_in(r, 2) ? V_RGB : V_RGBA, bpp = fmt == V_RGB ? 3 : 4;
    size_t n = (size_t)w * h * bpp;
    if (one_in(r, 8))
        n = below(r, (uint32_t)n + 16);
    if (n > 4096)
        n = 4096;
    fz_res *res = &t->res[t->nres++];
    uint32_t id = (uint32_t)t->nres;
    res->kind = RGL_RES_BYTES;
    res->data.n = 0;
    buf_reserve(&res->data, n);
    for (size_t k = 0; k < n; k++)
        res->data.p[k] = (uint8_t)rnd(r);
    res->data.n = n;
    put_op(g, b, RGL_OP_GenTextures, NULL, 0, NULL, 0);
    PUT(g, b, BindTexture, V_TEXTURE_2D, one_in(r, 4) ? below(r, 3) : 1);
    if (one_in(r, 4))
        PUT(g, b, Build2DMipmaps, V_TEXTURE_2D, bpp, w, h, fmt, V_UNSIGNED_BYTE, id);
    else
        PUT(g, b, TexImage2D, V_TEXTURE_2D, one_in(r, 6) ? below(r, 3) : 0, bpp, w, h, 0, fmt,
            V_UNSIGNED_BYTE, id);
    if (one_in(r, 2))
        put_row(g, b, rgl_cmd_info_get(RGL_OP_TexParameteri));
    if (one_in(r, 3))
        put_row(g, b, rgl_cmd_info_get(RGL_OP_TexEnvi));
    PUT(g, b, Enable, V_TEXTURE_2D);
    PUT(g, b, Begin, V_TRIANGLES);
    for (int k = 0; k < 3; k++) {
        PUT(g, b, TexCoord2f, (double)below(r, 3) - 1, (double)below(r, 3) - 1);
        PUT(g, b, Vertex3f, (double)below(r, 3) - 1, (double)below(r, 3) - 1, 0);
    }
    PUT(g, b, End, 0);
}

static void st_light(gen *g, buf *b)
{
    rng *r = &g->r;
    PUT(g, b, Enable, V_LIGHTING);
    PUT(g, b, Enable, V_LIGHT0 + below(r, 8));
    uint32_t n = 1 + below(r, 3);
    for (uint32_t k = 0; k < n; k++)
        put_row(g, b, rgl_cmd_info_get(one_in(r, 2) ? RGL_OP_Lightfv : RGL_OP_Materialfv));
    if (one_in(r, 2))
        PUT(g, b, Enable, V_DEPTH_TEST);
}

/* Something that draws (or sets state), at most `depth` levels of lists. */
static void st_draw(gen *g, buf *b, int depth)
{
    rng *r = &g->r;
    switch (below(r, depth ? 8 : 10)) {
    case 0:
    case 1:
        st_prim(g, b);
        break;
    case 2:
        if (one_in(r, 3))
            st_nurbs(g, b);
        else
            st_shape(g, b);
        break;
    case 3:
        st_xform(g, b);
        break;
    case 4:
        st_array(g, b);
        break;
    case 5:
        st_light(g, b);
        break;
    case 6:
        st_texture(g, b);
        break;
    case 7:
        put_row(g, b, rows.all[below(r, (uint32_t)rows.nall)]);
        break;
    default:
        st_list(g, b);
        break;
    }
}

/* ---- Whole traces ------------------------------------------------------------------------ */

static void gen_trace(gen *g)
{
    rng *r = &g->r;
    fz_trace *t = g->t;
    uint32_t frames = 1 + (one_in(r, 2) ? below(r, 3) : 0);
    t->index = !one_in(r, 4);
    for (uint32_t f = 0; f < frames && t->nfr < FZ_MAX_FRAMES; f++) {
        fz_frame *x = &t->fr[t->nfr++];
        x->stream = one_in(r, 8) ? 1 : 0;
        x->number = f;
        x->flags = f && !one_in(r, 4) ? RGL_FRAME_STATE_CARRIED : below(r, 2);
        x->cmds.n = 0;
        if (one_in(r, 4))
            PUT(g, &x->cmds, FrameBegin, 0, 0, 5, 0, 0, 0, 5, 5, 5);
        uint32_t parts = 1 + below(r, 4);
        for (uint32_t k = 0; k < parts; k++)
            st_draw(g, &x->cmds, 0);
        if (one_in(r, 2))
            PUT(g, &x->cmds, SwapBuffers, 0);
    }
    /* a state snapshot for the first frame, now and then */
    if (one_in(r, 6) && t->nres < FZ_MAX_RES) {
        fz_res *res = &t->res[t->nres++];
        res->kind = RGL_RES_COMMANDS;
        res->data.n = 0;
        st_light(g, &res->data);
        t->fr[0].state = (uint32_t)t->nres;
    }
}

static void gen_init(gen *g, fz_trace *t, uint32_t seed)
{
    rows_init();
    memset(g, 0, sizeof *g);
    g->r.s = 0x5eed0000ull ^ ((uint64_t)seed << 17) ^ seed;
    g->t = t;
    /* the list names the trace already defines, for calls to reach them */
    for (size_t i = 0; i < t->nfr + t->nres; i++) {
        buf *b = i < t->nfr ? &t->fr[i].cmds : &t->res[i - t->nfr].data;
        rgl_cmd_iter it;
        if (i >= t->nfr && t->res[i - t->nfr].kind != RGL_RES_COMMANDS)
            continue;
        rgl_cmd_iter_init(&it, b->p ? b->p : (const uint8_t *)"", b->n, 0);
        while (rgl_cmd_next(&it, &g_cmd) == RGL_OK && g->nlists < 16)
            if (g_cmd.opcode == RGL_OP_NewList)
                g->lists[g->nlists++] = (uint32_t)g_cmd.arg[0].v.u;
    }
}

size_t fuzzgen_generate(uint8_t *out, size_t max_size, uint32_t seed)
{
    fz_trace t;
    gen g;
    size_t n = 0;
    memset(&t, 0, sizeof t);
    for (uint32_t attempt = 0; attempt < 8 && !n; attempt++) {
        trace_free(&t);
        gen_init(&g, &t, seed + attempt * 0x10001u);
        gen_trace(&g);
        n = trace_to_bytes(&t, out, max_size);
    }
    trace_free(&t);
    return n;
}

/* ---- Mutations -------------------------------------------------------------------------- */

/* A command sequence of the model: a frame's or a COMMANDS resource's. */
static buf *pick_seq(gen *g)
{
    fz_trace *t = g->t;
    buf *c[FZ_MAX_FRAMES + FZ_MAX_RES];
    size_t n = 0;
    for (size_t i = 0; i < t->nfr; i++)
        c[n++] = &t->fr[i].cmds;
    for (size_t i = 0; i < t->nres; i++)
        if (t->res[i].kind == RGL_RES_COMMANDS)
            c[n++] = &t->res[i].data;
    return n ? c[below(&g->r, (uint32_t)n)] : NULL;
}

/* Changes one argument of one command to a value picked for its type. */
static void mut_arg(gen *g, buf *b, const span *sp, size_t n)
{
    rng *r = &g->r;
    rgl_cmd_iter it;
    if (!n)
        return;
    const span *s = &sp[below(r, (uint32_t)n)];
    rgl_cmd_iter_init(&it, b->p + s->off, s->len, 0);
    if (rgl_cmd_next(&it, &g_cmd) != RGL_OK || !g_cmd.nargs)
        return;
    static double elems[2 * RGL_ARRAY_MAX];
    uint32_t i = below(r, g_cmd.nargs);
    rgl_arg *a = &g_cmd.arg[i];
    const rgl_arg_desc *d = &g_cmd.info->args[i];
    switch (a->kind) {
    case RGL_ARG_SCALAR:
        if (one_in(r, 3) && d->type != RGL_T_f && d->type != RGL_T_d) {
            int64_t delta = (int64_t)below(r, 9) - 4; /* a neighbour: GL_LIGHT0 + k */
            if (d->type == RGL_T_b || d->type == RGL_T_s || d->type == RGL_T_i ||
                d->type == RGL_T_sz || d->type == RGL_T_ip)
                a->v.i = (int64_t)((uint64_t)a->v.i + (uint64_t)delta); /* wraps, as v.u */
            else
                a->v.u += (uint64_t)delta;
        } else {
            pick_scalar(g, g_cmd.info, d, a);
        }
        break;
    case RGL_ARG_ARRAY:
    case RGL_ARG_COUNTED:
        memcpy(elems, a->array, a->count * sizeof(double));
        if (a->kind == RGL_ARG_COUNTED && one_in(r, 3))
            a->count = one_in(r, 2) ? below(r, 5) : below(r, RGL_ARRAY_MAX + 1);
        for (uint32_t k = 0; k < a->count; k++)
            if (k >= a->count / 2 || one_in(r, 2))
                elems[k] = one_in(r, 3) ? elems[k] : pick_element(g, d->type);
        a->array = elems;
        break;
    default: {
        uint32_t len = a->count;
        if (len > sizeof g_bytes)
            return;
        memcpy(g_bytes, a->bytes, len);
        if (one_in(r, 2) || !len)
            len = one_in(r, 2) ? below(r, len + 16) : len * 2 + 1;
        if (len > sizeof g_bytes)
            len = sizeof g_bytes;
        for (uint32_t k = a->count; k < len; k++)
            g_bytes[k] = (uint8_t)below(r, 8);
        if (len && one_in(r, 2))
            g_bytes[below(r, len)] = (uint8_t)rnd(r);
        a->bytes = g_bytes;
        a->count = len;
        break;
    }
    }
    size_t m = rgl_cmd_encode(&g_cmd, g_enc, sizeof g_enc);
    if (!m)
        return;
    buf_erase(b, s->off, s->len);
    buf_insert(b, s->off, g_enc, m);
}

/* A new command sequence from st_draw, inserted at position `at` of b. */
static void insert_generated(gen *g, buf *b, size_t at, bool single)
{
    buf tmp = {0};
    if (single)
        put_row(g, &tmp, rows.all[below(&g->r, (uint32_t)rows.nall)]);
    else
        st_draw(g, &tmp, 0);
    /* st_list may have added a resource; b still points at valid storage
     * (the model's arrays do not move) */
    buf_insert(b, at, tmp.p, tmp.n);
    free(tmp.p);
}

static void mutate_model(gen *g, fuzzgen_bytes_fn bytes)
{
    static span sp[FZ_MAX_SPANS];
    rng *r = &g->r;
    fz_trace *t = g->t;
    buf *b = pick_seq(g);
    size_t n = b ? seq_spans(b, sp, FZ_MAX_SPANS, true) : 0;
    size_t at = n ? sp[below(r, (uint32_t)n)].off : 0;
    if (n && one_in(r, 2))
        at = b->n;

    switch (below(r, 16)) {
    case 0:
    case 1:
        if (b)
            insert_generated(g, b, at, true);
        break;
    case 2:
    case 3:
    case 4:
        if (b)
            insert_generated(g, b, at, false);
        break;
    case 5: /* delete a run of commands */
        if (n) {
            size_t i = below(r, (uint32_t)n), k = 1 + below(r, 4);
            if (i + k > n)
                k = n - i;
            buf_erase(b, sp[i].off, sp[i + k - 1].off + sp[i + k - 1].len - sp[i].off);
        }
        break;
    case 6: /* duplicate a run, here or in another sequence */
        if (n) {
            size_t i = below(r, (uint32_t)n), k = 1 + below(r, 4);
            if (i + k > n)
                k = n - i;
            size_t off = sp[i].off, len = sp[i + k - 1].off + sp[i + k - 1].len - off;
            uint8_t *copy = xrealloc(NULL, len);
            memcpy(copy, b->p + off, len);
            buf *to = one_in(r, 3) ? pick_seq(g) : b;
            size_t where = to == b ? at : to->n;
            if (to != b && to->n && one_in(r, 2)) {
                static span sp2[FZ_MAX_SPANS];
                size_t n2 = seq_spans(to, sp2, FZ_MAX_SPANS, true);
                where = n2 ? sp2[below(r, (uint32_t)n2)].off : 0;
            }
            buf_insert(to, where, copy, len);
            free(copy);
        }
        break;
    case 7: /* swap two commands */
        if (n >= 2) {
            size_t i = below(r, (uint32_t)n), j = below(r, (uint32_t)n);
            if (i > j) {
                size_t x = i;
                i = j;
                j = x;
            }
            if (i != j) {
                span a = sp[i], c = sp[j];
                uint8_t *tmp = xrealloc(NULL, c.off + c.len - a.off);
                size_t mid = c.off - (a.off + a.len), k = 0;
                memcpy(tmp + k, b->p + c.off, c.len), k += c.len;
                memcpy(tmp + k, b->p + a.off + a.len, mid), k += mid;
                memcpy(tmp + k, b->p + a.off, a.len), k += a.len;
                memcpy(b->p + a.off, tmp, k);
                free(tmp);
            }
        }
        break;
    case 8:
    case 9:
    case 10:
        if (b)
            mut_arg(g, b, sp, n);
        break;
    case 11: /* frames: add one carrying state, drop one, change its header */
        if (t->nfr < FZ_MAX_FRAMES && (one_in(r, 2) || !t->nfr)) {
            fz_frame *x = &t->fr[t->nfr];
            x->stream = t->nfr ? t->fr[t->nfr - 1].stream : 0;
            x->number = t->nfr ? t->fr[t->nfr - 1].number + 1 : 0;
            x->flags = RGL_FRAME_STATE_CARRIED;
            x->state = 0;
            x->cmds.n = 0;
            t->nfr++;
            if (t->nfr > 1 && one_in(r, 2)) {
                const buf *from = &t->fr[below(r, (uint32_t)t->nfr - 1)].cmds;
                buf_set(&x->cmds, from->p, from->n);
            } else
                st_draw(g, &x->cmds, 0);
        } else if (t->nfr > 1 && one_in(r, 2)) {
            size_t i = below(r, (uint32_t)t->nfr);
            free(t->fr[i].cmds.p);
            memmove(&t->fr[i], &t->fr[i + 1], (t->nfr - i - 1) * sizeof t->fr[0]);
            t->nfr--;
            memset(&t->fr[t->nfr], 0, sizeof t->fr[0]);
        } else if (t->nfr) {
            fz_frame *x = &t->fr[below(r, (uint32_t)t->nfr)];
            switch (below(r, 4)) {
            case 0: x->flags = below(r, 8); break;
            case 1: x->state = below(r, (uint32_t)t->nres + 2); break;
            case 2: x->stream = below(r, 3); break;
            default: x->number = below(r, 4); break;
            }
        }
        break;
    case 12: /* resources: a new list body or bytes, resized bytes, a kind flip */
        if (t->nres < FZ_MAX_RES && one_in(r, 2)) {
            if (b)
                st_list(g, b);
        } else if (t->nres) {
            fz_res *x = &t->res[below(r, (uint32_t)t->nres)];
            if (one_in(r, 4)) {
                x->kind = x->kind == RGL_RES_COMMANDS ? RGL_RES_BYTES : RGL_RES_COMMANDS;
                if (x->kind == RGL_RES_COMMANDS) /* bytes as commands: what decodes */
                    seq_spans(&x->data, sp, FZ_MAX_SPANS, true);
            } else if (x->kind == RGL_RES_BYTES) {
                size_t len = below(r, (uint32_t)x->data.n * 2 + 16);
                buf_reserve(&x->data, len > x->data.n ? len - x->data.n : 0);
                for (size_t k = x->data.n; k < len; k++)
                    x->data.p[k] = (uint8_t)rnd(r);
                x->data.n = len;
            }
        }
        break;
    case 13: /* a list called from its own body or another's: fan-out */
        for (size_t i = 0; i < t->nres; i++) {
            fz_res *x = &t->res[(i + below(r, (uint32_t)t->nres)) % t->nres];
            if (x->kind != RGL_RES_COMMANDS || !g->nlists)
                continue;
            uint32_t k = 1 + below(r, 3);
            for (uint32_t j = 0; j < k; j++)
                PUT(g, &x->data, CallList, g->lists[below(r, (uint32_t)g->nlists)]);
            break;
        }
        break;
    case 14: /* bytes of one sequence, framing kept */
        if (b && bytes) {
            size_t cap = b->n * 2 + 64;
            buf_reserve(b, cap - b->n);
            b->n = bytes(b->p, b->n, cap);
        }
        break;
    default:
        t->index = !t->index;
        break;
    }
}

static size_t shrink_to_fit(gen *g, uint8_t *out, size_t max_size)
{
    static span sp[FZ_MAX_SPANS];
    fz_trace *t = g->t;
    for (int tries = 0; tries < 64; tries++) {
        size_t n = trace_to_bytes(t, out, max_size);
        if (n)
            return n;
        /* too big: drop commands from the longest sequence, or bytes */
        buf *big = NULL;
        for (size_t i = 0; i < t->nfr + t->nres; i++) {
            buf *b = i < t->nfr ? &t->fr[i].cmds : &t->res[i - t->nfr].data;
            if (!big || b->n > big->n)
                big = b;
        }
        if (!big || !big->n)
            break;
        size_t k = seq_spans(big, sp, FZ_MAX_SPANS, false);
        if (k > 1)
            big->n = sp[k / 2].off;
        else
            big->n /= 2;
    }
    return 0;
}

size_t fuzzgen_mutate(uint8_t *data, size_t size, size_t max_size, uint32_t seed,
                      fuzzgen_bytes_fn bytes)
{
    fz_trace t;
    gen g;
    rng r = {seed};
    size_t n;

    rnd(&r);
    /* now and then the plain byte mutator on the whole input, so framing
     * and header damage stay reachable */
    if (bytes && one_in(&r, 8))
        return bytes(data, size, max_size);
    if (one_in(&r, 32) || size == 0)
        return (n = fuzzgen_generate(data, max_size, seed)) ? n : size;
    trace_from_bytes(&t, data, size);
    gen_init(&g, &t, seed);
    if (!t.nfr && !t.nres)
        gen_trace(&g);
    uint32_t rounds = 1 + (one_in(&g.r, 2) ? below(&g.r, 4) : 0);
    for (uint32_t k = 0; k < rounds; k++)
        mutate_model(&g, bytes);
    n = shrink_to_fit(&g, data, max_size);
    trace_free(&t);
    return n ? n : size;
}

size_t fuzzgen_crossover(const uint8_t *a, size_t asize, const uint8_t *b, size_t bsize,
                         uint8_t *out, size_t max_size, uint32_t seed)
{
    static span sp[FZ_MAX_SPANS];
    fz_trace ta, tb;
    gen g;
    size_t n;

    trace_from_bytes(&ta, a, asize);
    trace_from_bytes(&tb, b, bsize);
    gen_init(&g, &ta, seed);
    rng *r = &g.r;
    if (one_in(r, 2)) {
        /* a run of b's commands into one of a's sequences */
        buf *to = pick_seq(&g), *from;
        g.t = &tb;
        from = pick_seq(&g);
        g.t = &ta;
        size_t k = from ? seq_spans(from, sp, FZ_MAX_SPANS, true) : 0;
        if (to && k) {
            size_t i = below(r, (uint32_t)k), j = i + below(r, (uint32_t)(k - i));
            size_t off = sp[i].off, len = sp[j].off + sp[j].len - off;
            buf_insert(to, one_in(r, 2) ? to->n : 0, from->p + off, len);
        }
    } else {
        /* b's resources after a's, and b's frames (their references moved
         * by a's resource count) after a's frames */
        size_t shift = ta.nres;
        for (size_t i = 0; i < tb.nres && ta.nres < FZ_MAX_RES; i++) {
            ta.res[ta.nres].kind = tb.res[i].kind;
            buf_set(&ta.res[ta.nres].data, tb.res[i].data.p, tb.res[i].data.n);
            ta.nres++;
        }
        for (size_t i = 0; i < tb.nfr && ta.nfr < FZ_MAX_FRAMES; i++) {
            fz_frame *x = &ta.fr[ta.nfr++];
            x->stream = tb.fr[i].stream;
            x->number = tb.fr[i].number;
            x->flags = tb.fr[i].flags;
            x->state = tb.fr[i].state ? tb.fr[i].state + (uint32_t)shift : 0;
            buf_set(&x->cmds, tb.fr[i].cmds.p, tb.fr[i].cmds.n);
        }
    }
    n = shrink_to_fit(&g, out, max_size);
    trace_free(&ta);
    trace_free(&tb);
    return n;
}
