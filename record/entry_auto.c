/* entry_auto.c: the recorder entry points generated from format/commands.def.
 *
 * For each AUTO or PRIM row this file defines raygl<Name> with the GL
 * prototype: reserve the command's worst-case size in the thread's buffer,
 * encode opcode and arguments, commit, then make the real call. PRIM rows
 * first record the resolved matrices (the call draws). A pointer argument
 * that is NULL is not read: the call is forwarded unrecorded, as GL would
 * fault on it or reject it.
 */
#define GL_GLEXT_PROTOTYPES 1 /* GL 1.4 and EXT rows (glWindowPos, glFogCoord, glSecondaryColor) */
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glu.h>
#include <GL/freeglut.h>

#include "raygl.h"
#include "recorder.h"

/* Worst-case encoded size of each argument. */
#define RGL_SIZE_P(t, n) +RGL_WMAX_##t
#define RGL_SIZE_A(t, n, c) +(c) * RGL_WMAX_##t
#define RGL_SIZE_N(t, n, c) +RGL_VARINT32_MAX + (size_t)RGL_ARRAY_MAX * RGL_WMAX_##t
#define RGL_SIZE_STR(n) +RGL_VARINT32_MAX + RGL_STRING_MAX
#define RGL_SIZE_NOARGS

/* Pointer arguments that are NULL. */
#define RGL_ISNULL_P(t, n)
#define RGL_ISNULL_A(t, n, c) || !(n)
#define RGL_ISNULL_N(t, n, c) || !(n)
#define RGL_ISNULL_STR(n) || !(n)
#define RGL_ISNULL_NOARGS

/* Encoding. An N() count beyond RGL_ARRAY_MAX is a bad pname to GL; its
 * elements are not read (count 0 keeps the record decodable). */
#define RGL_ENC_P(t, n) p = rgl_put_##t(p, n);
#define RGL_ENC_A(t, n, c)                  \
    for (unsigned k_ = 0; k_ < (c); k_++) \
        p = rgl_put_##t(p, (n)[k_]);
#define RGL_ENC_N(t, n, c)                              \
    {                                                   \
        uint32_t c_ = (uint32_t)(c);                    \
        if (c_ > RGL_ARRAY_MAX)                         \
            c_ = 0;                                     \
        p = rgl_put_varint(p, c_);                      \
        for (uint32_t k_ = 0; k_ < c_; k_++)            \
            p = rgl_put_##t(p, (n)[k_]);                \
    }
#define RGL_ENC_STR(n)                                   \
    {                                                    \
        size_t l_ = strnlen(n, RGL_STRING_MAX);          \
        p = rgl_put_varint(p, l_);                       \
        memcpy(p, n, l_);                                \
        p += l_;                                         \
    }
#define RGL_ENC_NOARGS

#define RGL_CALL_P(t, n) n
#define RGL_CALL_A(t, n, c) n
#define RGL_CALL_N(t, n, c) n
#define RGL_CALL_STR(n) n
#define RGL_CALL_NOARGS

/* GLUT's shapes make freeglut exit when glutInit has not run (batch use
 * with no window): only forward them once it has. */
#define RGL_FORWARD_GUARD_GL
#ifdef RGL_FORWARD_H
/* GLU and GLUT draw through their own gl* imports: choose the thread's GL
 * (and point those at it, forward.h) before the first shape too. */
#define RGL_FORWARD_GUARD_GLU if (RGL_FWD_TABLE())
#define RGL_FORWARD_GUARD_GLUT if (RGL_FWD_TABLE() && rgl_glut_ready())
#else
#define RGL_FORWARD_GUARD_GLU
#define RGL_FORWARD_GUARD_GLUT if (rgl_glut_ready())
#endif

/* Whether GL is between glBegin and glEnd, for rgl_resolve_matrices (op
 * is a constant: this folds away for every other row). A glBegin compiled
 * into a list with GL_COMPILE does not execute. */
static inline void track_begin(rgl_stream *s, uint32_t op)
{
    if ((op == RGL_OP_Begin || op == RGL_OP_End) &&
        (!s->compiling || s->list_mode == GL_COMPILE_AND_EXECUTE))
        s->in_begin = op == RGL_OP_Begin;
}

#define RGL_RECORD_BODY(op, ...)                                                      \
    rgl_stream *s_;                                                                   \
    uint8_t *p = rgl_reserve(&s_, 2 RGL_MAP(RGL_SIZE_, __VA_ARGS__));                 \
    if (p && !(0 RGL_MAP(RGL_ISNULL_, __VA_ARGS__))) {                                \
        p = rgl_put_opcode(p, op);                                                    \
        RGL_MAP(RGL_ENC_, __VA_ARGS__)                                                \
        rgl_commit(s_, p);                                                            \
        track_begin(s_, op);                                                          \
    }

#define RGL_GEN_AUTO(op, api, name, ...)                                              \
    RGL_EXPORT void RGL_APIFN(api, name)(RGL_MAP_LIST(RGL_PROTO_, __VA_ARGS__))        \
    {                                                                                 \
        RGL_RECORD_BODY(op, __VA_ARGS__)                                              \
        RGL_FORWARD_GUARD_##api RGL_REALFN(api, name)(RGL_MAP_LIST(RGL_CALL_, __VA_ARGS__)); \
    }

#define RGL_GEN_PRIM(op, api, name, ...)                                              \
    RGL_EXPORT void RGL_APIFN(api, name)(RGL_MAP_LIST(RGL_PROTO_, __VA_ARGS__))        \
    {                                                                                 \
        rgl_resolve_matrices();                                                       \
        RGL_RECORD_BODY(op, __VA_ARGS__)                                              \
        RGL_FORWARD_GUARD_##api RGL_REALFN(api, name)(RGL_MAP_LIST(RGL_CALL_, __VA_ARGS__)); \
    }

#define RGL_GEN_CUSTOM(op, api, name, ...)
#define RGL_GEN_WIRE(op, api, name, ...)

#define RGL_CMD(op, api, gen, name, handler, ...) RGL_GEN_##gen(op, api, name, __VA_ARGS__)
#include "commands.def"
#undef RGL_CMD
