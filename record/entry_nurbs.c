/* entry_nurbs.c: the recorder entry points of GLU's NURBS calls (rows with
 * gen CUSTOM in format/commands.def).
 *
 * A NURBS object is a process-wide pointer; the trace names it by a small
 * id, as a quadric. Knots and control points are copied into the record as
 * GLU reads them: sKnotCount - sOrder by tKnotCount - tOrder points, point
 * (i, j) at control + i * sStride + j * tStride, k values each (k fixed by
 * the type). A call whose sizes GLU rejects (an order below 1, fewer knots
 * than 2 * order... see nurbs_sizes) is forwarded without being recorded.
 *
 * GLU draws at gluEndSurface and gluEndCurve: those record the matrices
 * first, as a shape does. In libraygl-preload.so every glu* call here goes
 * through the passthrough guard (tools/gen_preload.c), so the GL calls GLU
 * makes to draw are not recorded a second time; with the twins GLU calls
 * libGL directly. In GLU_NURBS_TESSELLATOR mode GLU draws nothing and hands
 * the pieces to the program's callbacks, whose GL calls are the program's
 * own: there the guard is lifted around the call.
 */
#include <GL/gl.h>
#include <GL/glu.h>
#include <pthread.h>

#include "raygl.h"
#include "recorder.h"

/* GLU's largest order (its MAXORDER); larger ones are errors. */
#define NURBS_MAX_ORDER 24
/* Most control points of one call recorded: a bound on the record's size,
 * far above what any program draws. */
#define NURBS_MAX_POINTS (1u << 20)

static struct {
    pthread_mutex_t mu;
    struct nurbs_entry { const GLUnurbs *n; uint32_t id; bool tess; } *v;
    size_t n, cap;
    uint32_t next;
} nobjs = {.mu = PTHREAD_MUTEX_INITIALIZER};

/* The id of n (a new one when first seen; 0 when out of memory); forget:
 * drop it. *tess (may be NULL) gets whether n is in tessellator mode, which
 * set_tess (-1: leave) changes. */
static uint32_t nurbs_id(const GLUnurbs *n, bool forget, int set_tess, bool *tess)
{
    uint32_t id = 0;
    bool t = false;
    pthread_mutex_lock(&nobjs.mu);
    for (size_t i = 0; i < nobjs.n; i++) {
        if (nobjs.v[i].n == n) {
            id = nobjs.v[i].id;
            if (set_tess >= 0)
                nobjs.v[i].tess = set_tess;
            t = nobjs.v[i].tess;
            if (forget)
                nobjs.v[i] = nobjs.v[--nobjs.n];
            goto out;
        }
    }
    if (forget)
        goto out;
    if (nobjs.n == nobjs.cap) {
        size_t cap = nobjs.cap ? 2 * nobjs.cap : 8;
        struct nurbs_entry *v = rgl_realloc(nobjs.v, cap * sizeof *v);
        if (!v)
            goto out;
        nobjs.v = v;
        nobjs.cap = cap;
    }
    id = ++nobjs.next;
    t = set_tess > 0;
    nobjs.v[nobjs.n++] = (struct nurbs_entry){n, id, t};
out:
    pthread_mutex_unlock(&nobjs.mu);
    if (tess)
        *tess = t;
    return id;
}

/* In the preload library the real glu* call is wrapped in the guard (one
 * level up); in tessellator mode that level is taken back for the call. */
#ifdef RGL_PRELOAD_REAL_H
#define TESS_UNGUARD(t) \
    do { if (t) rgl_tls_passthrough--; } while (0)
#define TESS_REGUARD(t) \
    do { if (t) rgl_tls_passthrough++; } while (0)
#else
#define TESS_UNGUARD(t) (void)(t)
#define TESS_REGUARD(t) (void)(t)
#endif

RGL_EXPORT GLUnurbs *raygluNewNurbsRenderer(void)
{
    GLUnurbs *n = gluNewNurbsRenderer();
    rgl_stream *s;
    if (n && rgl_reserve(&s, 1))
        rgl_record(RGL_OP_NewNurbsRenderer, "e", nurbs_id(n, false, 0, NULL));
    return n;
}

RGL_EXPORT void raygluDeleteNurbsRenderer(GLUnurbs *nurb)
{
    rgl_stream *s;
    if (nurb && rgl_reserve(&s, 1))
        rgl_record(RGL_OP_DeleteNurbsRenderer, "e", nurbs_id(nurb, true, -1, NULL));
    else if (nurb)
        nurbs_id(nurb, true, -1, NULL);
    gluDeleteNurbsRenderer(nurb);
}

RGL_EXPORT void raygluNurbsProperty(GLUnurbs *nurb, GLenum property, GLfloat value)
{
    if (nurb) {
        int tess = property == GLU_NURBS_MODE ? (GLenum)value == GLU_NURBS_TESSELLATOR : -1;
        if (property == GLU_NURBS_MODE && (GLenum)value != GLU_NURBS_TESSELLATOR &&
            (GLenum)value != GLU_NURBS_RENDERER)
            tess = -1; /* GLU rejects it: the mode stays */
        uint32_t id = nurbs_id(nurb, false, tess, NULL);
        rgl_stream *s;
        if (rgl_reserve(&s, 1))
            rgl_record(RGL_OP_NurbsProperty, "eef", id, property, (double)value);
    }
    gluNurbsProperty(nurb, property, value);
}

RGL_EXPORT void raygluLoadSamplingMatrices(GLUnurbs *nurb, const GLfloat *model,
                                           const GLfloat *perspective, const GLint *view)
{
    rgl_stream *s;
    if (nurb && model && perspective && view && rgl_reserve(&s, 1))
        rgl_record(RGL_OP_LoadSamplingMatrices, "eAAiiii", nurbs_id(nurb, false, -1, NULL), model,
                   16, perspective, 16, view[0], view[1], view[2], view[3]);
    gluLoadSamplingMatrices(nurb, model, perspective, view);
}

/* gluBegin*: one record naming the object. */
static void nurbs_mark(uint32_t op, const GLUnurbs *nurb, bool *tess)
{
    *tess = false;
    if (!nurb)
        return;
    uint32_t id = nurbs_id(nurb, false, -1, tess);
    rgl_stream *s;
    if (rgl_reserve(&s, 1))
        rgl_record(op, "e", id);
}

/* gluEnd{Surface,Curve}: GLU draws now, with the current matrices. */
static void nurbs_draw_mark(uint32_t op, const GLUnurbs *nurb, bool *tess)
{
    if (nurb)
        rgl_resolve_matrices();
    nurbs_mark(op, nurb, tess);
}

/* glu{Begin,End}{Surface,Curve} as op: the record (an End draws now, with
 * the current matrices), then GLU's own call, outside the recorder's guard
 * when the object is a tessellator. The glu* calls are spelt out: in the
 * preload library each is a macro to the real GLU. */
static void nurbs_bracket(uint32_t op, GLUnurbs *nurb)
{
    bool t;
    if (op == RGL_OP_EndSurface || op == RGL_OP_EndCurve)
        nurbs_draw_mark(op, nurb, &t);
    else
        nurbs_mark(op, nurb, &t);
    TESS_UNGUARD(t);
    if (op == RGL_OP_BeginSurface)
        gluBeginSurface(nurb);
    else if (op == RGL_OP_EndSurface)
        gluEndSurface(nurb);
    else if (op == RGL_OP_BeginCurve)
        gluBeginCurve(nurb);
    else
        gluEndCurve(nurb);
    TESS_REGUARD(t);
}

RGL_EXPORT void raygluBeginSurface(GLUnurbs *nurb)
{
    nurbs_bracket(RGL_OP_BeginSurface, nurb);
}

RGL_EXPORT void raygluEndSurface(GLUnurbs *nurb)
{
    nurbs_bracket(RGL_OP_EndSurface, nurb);
}

RGL_EXPORT void raygluBeginCurve(GLUnurbs *nurb)
{
    nurbs_bracket(RGL_OP_BeginCurve, nurb);
}

RGL_EXPORT void raygluEndCurve(GLUnurbs *nurb)
{
    nurbs_bracket(RGL_OP_EndCurve, nurb);
}

RGL_EXPORT void raygluBeginTrim(GLUnurbs *nurb)
{
    bool t;
    nurbs_mark(RGL_OP_BeginTrim, nurb, &t);
    gluBeginTrim(nurb);
}

RGL_EXPORT void raygluEndTrim(GLUnurbs *nurb)
{
    bool t;
    nurbs_mark(RGL_OP_EndTrim, nurb, &t);
    gluEndTrim(nurb);
}

/* Values per point of a NURBS type: the GL map targets (k as glMap's) and
 * GLU's trim curves; 0 for anything else. */
static uint32_t nurbs_k(GLenum type, bool surface)
{
    if (!surface && type == GLU_MAP1_TRIM_2)
        return 2;
    if (!surface && type == GLU_MAP1_TRIM_3)
        return 3;
    bool two;
    uint32_t k = rgl_map_components(type, &two);
    return two == surface ? k : 0;
}

/* Points along one axis, or 0 when GLU rejects the sizes. */
static uint32_t nurbs_points(GLint knots, GLint order, GLint stride, uint32_t k)
{
    if (order < 1 || order > NURBS_MAX_ORDER || knots < 2 * order || stride < (GLint)k)
        return 0;
    return (uint32_t)(knots - order);
}

/* The fixed part's worst case: opcode, handle, six ints, an enum, three
 * blob lengths. */
#define NURBS_FIXED (2 + RGL_VARINT32_MAX * 8 + 3 * RGL_VARINT64_MAX)

static uint8_t *put_floats(uint8_t *p, const GLfloat *v, uint32_t n)
{
    p = rgl_put_varint(p, (uint64_t)n * 4);
    for (uint32_t i = 0; i < n; i++)
        p = rgl_put_f(p, v[i]);
    return p;
}

RGL_EXPORT void raygluNurbsSurface(GLUnurbs *nurb, GLint sKnotCount, GLfloat *sKnots,
                                   GLint tKnotCount, GLfloat *tKnots, GLint sStride,
                                   GLint tStride, GLfloat *control, GLint sOrder, GLint tOrder,
                                   GLenum type)
{
    uint32_t k = nurbs_k(type, true);
    uint32_t ns = k ? nurbs_points(sKnotCount, sOrder, sStride, k) : 0;
    uint32_t nt = k ? nurbs_points(tKnotCount, tOrder, tStride, k) : 0;
    if (nurb && ns && nt && sKnots && tKnots && control &&
        (uint64_t)ns * nt <= NURBS_MAX_POINTS) {
        uint32_t id = nurbs_id(nurb, false, -1, NULL);
        size_t n = (size_t)ns * nt * k;
        rgl_stream *s;
        uint8_t *p = rgl_reserve(&s, NURBS_FIXED + 4 * (n + (size_t)sKnotCount +
                                                        (size_t)tKnotCount));
        if (p) {
            p = rgl_put_opcode(p, RGL_OP_NurbsSurface);
            p = rgl_put_varint(p, id);
            p = rgl_put_i(p, sKnotCount);
            p = put_floats(p, sKnots, (uint32_t)sKnotCount);
            p = rgl_put_i(p, tKnotCount);
            p = put_floats(p, tKnots, (uint32_t)tKnotCount);
            p = rgl_put_i(p, sStride);
            p = rgl_put_i(p, tStride);
            p = rgl_put_varint(p, (uint64_t)n * 4);
            for (uint32_t i = 0; i < ns; i++)
                for (uint32_t j = 0; j < nt; j++)
                    for (uint32_t c = 0; c < k; c++)
                        p = rgl_put_f(p, control[(size_t)i * (size_t)sStride +
                                                 (size_t)j * (size_t)tStride + c]);
            p = rgl_put_i(p, sOrder);
            p = rgl_put_i(p, tOrder);
            p = rgl_put_varint(p, type);
            rgl_commit(s, p);
        }
    }
    gluNurbsSurface(nurb, sKnotCount, sKnots, tKnotCount, tKnots, sStride, tStride, control,
                    sOrder, tOrder, type);
}

RGL_EXPORT void raygluNurbsCurve(GLUnurbs *nurb, GLint knotCount, GLfloat *knots, GLint stride,
                                 GLfloat *control, GLint order, GLenum type)
{
    uint32_t k = nurbs_k(type, false);
    uint32_t np = k ? nurbs_points(knotCount, order, stride, k) : 0;
    if (nurb && np && knots && control && np <= NURBS_MAX_POINTS) {
        uint32_t id = nurbs_id(nurb, false, -1, NULL);
        size_t n = (size_t)np * k;
        rgl_stream *s;
        uint8_t *p = rgl_reserve(&s, NURBS_FIXED + 4 * (n + (size_t)knotCount));
        if (p) {
            p = rgl_put_opcode(p, RGL_OP_NurbsCurve);
            p = rgl_put_varint(p, id);
            p = rgl_put_i(p, knotCount);
            p = put_floats(p, knots, (uint32_t)knotCount);
            p = rgl_put_i(p, stride);
            p = rgl_put_varint(p, (uint64_t)n * 4);
            for (uint32_t i = 0; i < np; i++)
                for (uint32_t c = 0; c < k; c++)
                    p = rgl_put_f(p, control[(size_t)i * (size_t)stride + c]);
            p = rgl_put_i(p, order);
            p = rgl_put_varint(p, type);
            rgl_commit(s, p);
        }
    }
    gluNurbsCurve(nurb, knotCount, knots, stride, control, order, type);
}

RGL_EXPORT void raygluPwlCurve(GLUnurbs *nurb, GLint count, GLfloat *data, GLint stride,
                               GLenum type)
{
    uint32_t k = type == GLU_MAP1_TRIM_2 ? 2 : type == GLU_MAP1_TRIM_3 ? 3 : 0;
    if (nurb && k && data && count >= 2 && stride >= (GLint)k &&
        (uint32_t)count <= NURBS_MAX_POINTS) {
        uint32_t id = nurbs_id(nurb, false, -1, NULL);
        size_t n = (size_t)count * k;
        rgl_stream *s;
        uint8_t *p = rgl_reserve(&s, NURBS_FIXED + 4 * n);
        if (p) {
            p = rgl_put_opcode(p, RGL_OP_PwlCurve);
            p = rgl_put_varint(p, id);
            p = rgl_put_i(p, count);
            p = rgl_put_varint(p, (uint64_t)n * 4);
            for (GLint i = 0; i < count; i++)
                for (uint32_t c = 0; c < k; c++)
                    p = rgl_put_f(p, data[(size_t)i * (size_t)stride + c]);
            p = rgl_put_i(p, stride);
            p = rgl_put_varint(p, type);
            rgl_commit(s, p);
        }
    }
    gluPwlCurve(nurb, count, data, stride, type);
}
