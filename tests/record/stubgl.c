/* stubgl.c: the stub GL, GLU and GLUT of the recorder unit tests (see
 * stubgl.h). The recorder sources are built a second time against this file
 * instead of the real libraries, so the tests need no GPU and no display. */
#include <string.h>

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glu.h>
#include <GL/freeglut.h>

#include "raygl.h"
#include "stubgl.h"

stub_call stub_log[STUB_LOG_MAX];
size_t stub_nlog;
int stub_glut_ready = 1;

void stub_reset(void) { stub_nlog = 0; }

static stub_call *stub_begin(const char *name)
{
    static stub_call overflow;
    stub_call *c = stub_nlog < STUB_LOG_MAX ? &stub_log[stub_nlog] : &overflow;
    stub_nlog++;
    memset(c, 0, sizeof *c);
    c->name = name;
    return c;
}

void stub_log_name(const char *name) { (void)stub_begin(name); }

static void arg_v(stub_call *c, double v)
{
    c->v[c->nargs] = v;
    c->p[c->nargs++] = NULL;
}

static void arg_p(stub_call *c, const void *p)
{
    c->v[c->nargs] = 0;
    c->p[c->nargs++] = p;
}

/* ---- Generated: the rows with gen AUTO and PRIM -------------------------------- */

/* <GL/gl.h> declares the transpose-matrix calls with array parameters. */
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 11
#pragma GCC diagnostic ignored "-Warray-parameter"
#endif

#define STUB_LOG_P(t, n) arg_v(c, (double)(n));
#define STUB_LOG_A(t, n, cnt) arg_p(c, (const void *)(n));
#define STUB_LOG_N(t, n, cnt) arg_p(c, (const void *)(n));
#define STUB_LOG_STR(n) arg_p(c, (const void *)(n));
#define STUB_LOG_NOARGS

#define STUB_GEN_AUTO(op, api, name, ...)                                      \
    void RGL_REALFN(api, name)(RGL_MAP_LIST(RGL_PROTO_, __VA_ARGS__))          \
    {                                                                          \
        stub_call *c = stub_begin(RGL_NAMESTR(api, name));                     \
        (void)c;                                                               \
        RGL_MAP(STUB_LOG_, __VA_ARGS__)                                        \
    }
#define STUB_GEN_PRIM STUB_GEN_AUTO
#define STUB_GEN_CUSTOM(op, api, name, ...)
#define STUB_GEN_WIRE(op, api, name, ...)
#define RGL_CMD(op, api, gen, name, handler, ...) STUB_GEN_##gen(op, api, name, __VA_ARGS__)
#include "commands.def"
#undef RGL_CMD

/* ---- By hand: the real calls behind the CUSTOM rows ------------------------------ */

#define LOG0(n) (void)stub_begin(n)
#define LOGV(n, ...)                                                           \
    do {                                                                       \
        stub_call *c = stub_begin(n);                                          \
        double v_[] = {__VA_ARGS__};                                           \
        for (size_t k_ = 0; k_ < sizeof v_ / sizeof v_[0]; k_++)               \
            arg_v(c, v_[k_]);                                                  \
    } while (0)

void glArrayElement(GLint i) { LOGV("glArrayElement", i); }
void glDrawArrays(GLenum mode, GLint first, GLsizei count)
{
    LOGV("glDrawArrays", mode, first, count);
}
void glDrawElements(GLenum mode, GLsizei count, GLenum type, const GLvoid *indices)
{
    stub_call *c = stub_begin("glDrawElements");
    arg_v(c, mode);
    arg_v(c, count);
    arg_v(c, type);
    arg_p(c, indices);
}
void glDrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type,
                         const GLvoid *indices)
{
    stub_call *c = stub_begin("glDrawRangeElements");
    arg_v(c, mode);
    arg_v(c, start);
    arg_v(c, end);
    arg_v(c, count);
    arg_v(c, type);
    arg_p(c, indices);
}
/* No context: GL leaves the names untouched. */
void glGenTextures(GLsizei n, GLuint *textures)
{
    stub_call *c = stub_begin("glGenTextures");
    arg_v(c, n);
    arg_p(c, textures);
}
void glDeleteTextures(GLsizei n, const GLuint *textures)
{
    stub_call *c = stub_begin("glDeleteTextures");
    arg_v(c, n);
    arg_p(c, textures);
}
void glBindTexture(GLenum target, GLuint texture) { LOGV("glBindTexture", target, texture); }
void glPixelStorei(GLenum pname, GLint param) { LOGV("glPixelStorei", pname, param); }
void glTexImage1D(GLenum target, GLint level, GLint internalFormat, GLsizei width, GLint border,
                  GLenum format, GLenum type, const GLvoid *pixels)
{
    LOGV("glTexImage1D", target, level, internalFormat, width, border, format, type);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], pixels);
}
void glTexImage2D(GLenum target, GLint level, GLint internalFormat, GLsizei width, GLsizei height,
                  GLint border, GLenum format, GLenum type, const GLvoid *pixels)
{
    LOGV("glTexImage2D", target, level, internalFormat, width, height, border, format, type);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], pixels);
}
void glTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width,
                     GLsizei height, GLenum format, GLenum type, const GLvoid *pixels)
{
    LOGV("glTexSubImage2D", target, level, xoffset, yoffset, width, height, format, type);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], pixels);
}
void glTexParameterf(GLenum target, GLenum pname, GLfloat param)
{
    LOGV("glTexParameterf", target, pname, param);
}
void glTexParameteri(GLenum target, GLenum pname, GLint param)
{
    LOGV("glTexParameteri", target, pname, param);
}
void glTexParameterfv(GLenum target, GLenum pname, const GLfloat *params)
{
    LOGV("glTexParameterfv", target, pname);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], params);
}
void glTexParameteriv(GLenum target, GLenum pname, const GLint *params)
{
    LOGV("glTexParameteriv", target, pname);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], params);
}
GLuint glGenLists(GLsizei range)
{
    LOGV("glGenLists", range);
    return 0;
}
void glNewList(GLuint list, GLenum mode) { LOGV("glNewList", list, mode); }
void glEndList(void) { LOG0("glEndList"); }
void glCallLists(GLsizei n, GLenum type, const GLvoid *lists)
{
    LOGV("glCallLists", n, type);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], lists);
}
void glDeleteLists(GLuint list, GLsizei range) { LOGV("glDeleteLists", list, range); }
void glVertexPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
{
    LOGV("glVertexPointer", size, type, stride);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], ptr);
}
void glNormalPointer(GLenum type, GLsizei stride, const GLvoid *ptr)
{
    LOGV("glNormalPointer", type, stride);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], ptr);
}
void glColorPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
{
    LOGV("glColorPointer", size, type, stride);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], ptr);
}
void glTexCoordPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
{
    LOGV("glTexCoordPointer", size, type, stride);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], ptr);
}
void glEdgeFlagPointer(GLsizei stride, const GLvoid *ptr)
{
    LOGV("glEdgeFlagPointer", stride);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], ptr);
}
void glFogCoordPointer(GLenum type, GLsizei stride, const GLvoid *ptr)
{
    LOGV("glFogCoordPointer", type, stride);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], ptr);
}
void glFogCoordPointerEXT(GLenum type, GLsizei stride, const GLvoid *ptr)
{
    LOGV("glFogCoordPointerEXT", type, stride);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], ptr);
}
void glSecondaryColorPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
{
    LOGV("glSecondaryColorPointer", size, type, stride);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], ptr);
}
void glSecondaryColorPointerEXT(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr)
{
    LOGV("glSecondaryColorPointerEXT", size, type, stride);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], ptr);
}
void glInterleavedArrays(GLenum format, GLsizei stride, const GLvoid *pointer)
{
    LOGV("glInterleavedArrays", format, stride);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], pointer);
}
void glEnableClientState(GLenum array) { LOGV("glEnableClientState", array); }
void glClientActiveTexture(GLenum texture) { LOGV("glClientActiveTexture", texture); }
void glClientActiveTextureARB(GLenum texture) { LOGV("glClientActiveTextureARB", texture); }
void glDisableClientState(GLenum array) { LOGV("glDisableClientState", array); }

static char quadrics[16];
static unsigned nquadrics;
GLUquadric *gluNewQuadric(void)
{
    LOG0("gluNewQuadric");
    return (GLUquadric *)&quadrics[nquadrics++ % sizeof quadrics];
}
void gluDeleteQuadric(GLUquadric *q)
{
    stub_call *c = stub_begin("gluDeleteQuadric");
    arg_p(c, q);
}
#define QUAD_STATE(fn, T)                                                      \
    void fn(GLUquadric *q, T v)                                                \
    {                                                                          \
        stub_call *c = stub_begin(#fn);                                        \
        arg_p(c, q);                                                           \
        arg_v(c, v);                                                           \
    }
QUAD_STATE(gluQuadricDrawStyle, GLenum)
QUAD_STATE(gluQuadricNormals, GLenum)
QUAD_STATE(gluQuadricOrientation, GLenum)
QUAD_STATE(gluQuadricTexture, GLboolean)
void gluSphere(GLUquadric *q, GLdouble radius, GLint slices, GLint stacks)
{
    (void)q;
    LOGV("gluSphere", radius, slices, stacks);
}
void gluCylinder(GLUquadric *q, GLdouble base, GLdouble top, GLdouble height, GLint slices,
                 GLint stacks)
{
    (void)q;
    LOGV("gluCylinder", base, top, height, slices, stacks);
}
void gluDisk(GLUquadric *q, GLdouble inner, GLdouble outer, GLint slices, GLint loops)
{
    (void)q;
    LOGV("gluDisk", inner, outer, slices, loops);
}
void gluPartialDisk(GLUquadric *q, GLdouble inner, GLdouble outer, GLint slices, GLint loops,
                    GLdouble start, GLdouble sweep)
{
    (void)q;
    LOGV("gluPartialDisk", inner, outer, slices, loops, start, sweep);
}
GLint gluBuild2DMipmaps(GLenum target, GLint internalFormat, GLsizei width, GLsizei height,
                        GLenum format, GLenum type, const void *data)
{
    LOGV("gluBuild2DMipmaps", target, internalFormat, width, height, format, type);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], data);
    return 0;
}
static char nurbs_objs[16];
static unsigned nnurbs;
GLUnurbs *gluNewNurbsRenderer(void)
{
    LOG0("gluNewNurbsRenderer");
    return (GLUnurbs *)&nurbs_objs[nnurbs++ % sizeof nurbs_objs];
}
#define NURBS_MARK(fn)                                                         \
    void fn(GLUnurbs *n)                                                       \
    {                                                                          \
        stub_call *c = stub_begin(#fn);                                        \
        arg_p(c, n);                                                           \
    }
NURBS_MARK(gluDeleteNurbsRenderer)
NURBS_MARK(gluBeginSurface)
NURBS_MARK(gluEndSurface)
NURBS_MARK(gluBeginCurve)
NURBS_MARK(gluEndCurve)
NURBS_MARK(gluBeginTrim)
NURBS_MARK(gluEndTrim)
void gluNurbsProperty(GLUnurbs *n, GLenum property, GLfloat value)
{
    (void)n;
    LOGV("gluNurbsProperty", property, value);
}
void gluLoadSamplingMatrices(GLUnurbs *n, const GLfloat *model, const GLfloat *perspective,
                             const GLint *view)
{
    stub_call *c = stub_begin("gluLoadSamplingMatrices");
    arg_p(c, n);
    arg_p(c, model);
    arg_p(c, perspective);
    arg_p(c, view);
}
void gluNurbsSurface(GLUnurbs *n, GLint sKnotCount, GLfloat *sKnots, GLint tKnotCount,
                     GLfloat *tKnots, GLint sStride, GLint tStride, GLfloat *control,
                     GLint sOrder, GLint tOrder, GLenum type)
{
    (void)n;
    (void)sKnots;
    (void)tKnots;
    (void)control;
    LOGV("gluNurbsSurface", sKnotCount, tKnotCount, sStride, tStride, sOrder, tOrder, type);
}
void gluNurbsCurve(GLUnurbs *n, GLint knotCount, GLfloat *knots, GLint stride, GLfloat *control,
                   GLint order, GLenum type)
{
    (void)n;
    (void)knots;
    (void)control;
    LOGV("gluNurbsCurve", knotCount, stride, order, type);
}
void gluPwlCurve(GLUnurbs *n, GLint count, GLfloat *data, GLint stride, GLenum type)
{
    (void)n;
    (void)data;
    LOGV("gluPwlCurve", count, stride, type);
}
void glutSwapBuffers(void) { LOG0("glutSwapBuffers"); }

/* ---- Queries: GL with no current context changes nothing ---------------------- */

int glutGet(GLenum what) { return what == GLUT_INIT_STATE ? stub_glut_ready : 0; }
void glGetIntegerv(GLenum pname, GLint *v)
{
    for (size_t k = 0; k < stub_nints; k++)
        if (stub_ints[k].pname == pname)
            *v = stub_ints[k].value;
}
void glGetFloatv(GLenum pname, GLfloat *v) { (void)pname, (void)v; }
void glGetDoublev(GLenum pname, GLdouble *v) { (void)pname, (void)v; }
void glGetBooleanv(GLenum pname, GLboolean *v) { (void)pname, (void)v; }
void glGetLightfv(GLenum l, GLenum pname, GLfloat *v) { (void)l, (void)pname, (void)v; }
void glGetMapdv(GLenum t, GLenum q, GLdouble *v) { (void)t, (void)q, (void)v; }
void glGetClipPlane(GLenum p, GLdouble *v) { (void)p, (void)v; }
unsigned char stub_pstipple_holes[128];
void glGetPixelMapfv(GLenum map, GLfloat *values)
{
    LOGV("glGetPixelMapfv", map);
    values[0] = 0;
}
void glGetPolygonStipple(GLubyte *mask)
{
    LOG0("glGetPolygonStipple");
    for (int i = 0; i < 128; i++)
        mask[i] = (GLubyte)~stub_pstipple_holes[i];
}
void glGetMapiv(GLenum t, GLenum q, GLint *v) { (void)t, (void)q, (void)v; }
void glGetMaterialfv(GLenum f, GLenum pname, GLfloat *v) { (void)f, (void)pname, (void)v; }
void glGetTexGenfv(GLenum c, GLenum pname, GLfloat *v) { (void)c, (void)pname, (void)v; }
void glGetTexGeniv(GLenum c, GLenum pname, GLint *v) { (void)c, (void)pname, (void)v; }
void glGetTexEnvfv(GLenum t, GLenum pname, GLfloat *v) { (void)t, (void)pname, (void)v; }
void glGetTexEnviv(GLenum t, GLenum pname, GLint *v) { (void)t, (void)pname, (void)v; }
void glGetTexParameteriv(GLenum t, GLenum pname, GLint *v) { (void)t, (void)pname, (void)v; }
/* The frame snapshot's calls (record/frameimage.c): no context, no version,
 * so a snapshot never reaches them; logged in case one does. */
const GLubyte *glGetString(GLenum name)
{
    return name == GL_VERSION ? (const GLubyte *)stub_version : NULL;
}
void glReadBuffer(GLenum mode) { LOGV("glReadBuffer", mode); }
void glReadPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, void *p)
{
    (void)p;
    LOGV("glReadPixels", x, y, w, h, format, type);
}
GLboolean glIsEnabled(GLenum cap)
{
    (void)cap;
    return GL_FALSE;
}
GLboolean glIsTexture(GLuint t)
{
    (void)t;
    return GL_FALSE;
}
void glGetTexLevelParameteriv(GLenum t, GLint level, GLenum pname, GLint *v)
{
    (void)t, (void)level, (void)pname, (void)v;
}
void glGetTexImage(GLenum t, GLint level, GLenum format, GLenum type, GLvoid *pixels)
{
    (void)t, (void)level, (void)format, (void)type, (void)pixels;
}

/* ---- Multi-draws and buffer objects ------------------------------------------------- */

void glMultiDrawArrays(GLenum mode, const GLint *first, const GLsizei *count, GLsizei drawcount)
{
    LOGV("glMultiDrawArrays", mode, drawcount);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], first);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], count);
}
void glMultiDrawElements(GLenum mode, const GLsizei *count, GLenum type,
                         const void *const *indices, GLsizei drawcount)
{
    LOGV("glMultiDrawElements", mode, type, drawcount);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], count);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], indices);
}

/* A mapping: unlike GL without a context, the stub maps its own scratch
 * memory, so that a test can write through it. */
unsigned char stub_mapped[4096];

const char *stub_version;
stub_int stub_ints[8];
size_t stub_nints;
unsigned char stub_buffer[4096];
GLint stub_buffer_size, stub_buffer_mapped;

void glGetBufferParameteriv(GLenum t, GLenum pname, GLint *v)
{
    (void)t;
    if (stub_version)
        *v = pname == GL_BUFFER_SIZE ? stub_buffer_size : stub_buffer_mapped;
}
void glGetBufferSubData(GLenum t, GLintptr o, GLsizeiptr n, void *d)
{
    LOGV("glGetBufferSubData", t, (double)o, (double)n);
    if (o >= 0 && n >= 0 && (size_t)o + (size_t)n <= sizeof stub_buffer)
        memcpy(d, stub_buffer + o, (size_t)n);
}

#define STUB_BUFFERS(sfx)                                                                 \
    void glGenBuffers##sfx(GLsizei n, GLuint *b)                                          \
    {                                                                                     \
        LOGV("glGenBuffers" #sfx, n);                                                     \
        arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], b);                             \
    }                                                                                     \
    void glDeleteBuffers##sfx(GLsizei n, const GLuint *b)                                 \
    {                                                                                     \
        LOGV("glDeleteBuffers" #sfx, n);                                                  \
        arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], b);                             \
    }                                                                                     \
    void glBindBuffer##sfx(GLenum t, GLuint b) { LOGV("glBindBuffer" #sfx, t, b); }       \
    void glBufferData##sfx(GLenum t, GLsizeiptr n, const void *d, GLenum u)               \
    {                                                                                     \
        LOGV("glBufferData" #sfx, t, (double)n, u);                                       \
        arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], d);                             \
    }                                                                                     \
    void glBufferSubData##sfx(GLenum t, GLintptr o, GLsizeiptr n, const void *d)          \
    {                                                                                     \
        LOGV("glBufferSubData" #sfx, t, (double)o, (double)n);                            \
        arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], d);                             \
    }                                                                                     \
    void *glMapBuffer##sfx(GLenum t, GLenum a)                                            \
    {                                                                                     \
        LOGV("glMapBuffer" #sfx, t, a);                                                   \
        return stub_mapped;                                                               \
    }                                                                                     \
    GLboolean glUnmapBuffer##sfx(GLenum t)                                                \
    {                                                                                     \
        LOGV("glUnmapBuffer" #sfx, t);                                                    \
        return GL_TRUE;                                                                   \
    }
STUB_BUFFERS()
STUB_BUFFERS(ARB)

/* ---- Pixel rectangles ---------------------------------------------------------------- */

void glBitmap(GLsizei w, GLsizei h, GLfloat xo, GLfloat yo, GLfloat xm, GLfloat ym,
              const GLubyte *bitmap)
{
    LOGV("glBitmap", w, h, xo, yo, xm, ym);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], bitmap);
}
void glDrawPixels(GLsizei w, GLsizei h, GLenum format, GLenum type, const GLvoid *pixels)
{
    LOGV("glDrawPixels", w, h, format, type);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], pixels);
}
void glPolygonStipple(const GLubyte *mask)
{
    LOG0("glPolygonStipple");
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], mask);
}
void glCopyPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum type)
{
    LOGV("glCopyPixels", x, y, w, h, type);
}
void glPixelMapfv(GLenum map, GLsizei mapsize, const GLfloat *values)
{
    LOGV("glPixelMapfv", map, mapsize);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], values);
}
void glPixelMapuiv(GLenum map, GLsizei mapsize, const GLuint *values)
{
    LOGV("glPixelMapuiv", map, mapsize);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], values);
}
void glPixelMapusv(GLenum map, GLsizei mapsize, const GLushort *values)
{
    LOGV("glPixelMapusv", map, mapsize);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], values);
}
void glDrawBuffer(GLenum mode)
{
    LOGV("glDrawBuffer", mode);
}

/* ---- Texture copies and 3D textures (record/entry_texcopy.c) ----------------------- */

void glCopyTexImage1D(GLenum target, GLint level, GLenum internal, GLint x, GLint y, GLsizei w,
                      GLint border)
{
    LOGV("glCopyTexImage1D", target, level, internal, x, y, w, border);
}
void glCopyTexImage2D(GLenum target, GLint level, GLenum internal, GLint x, GLint y, GLsizei w,
                      GLsizei h, GLint border)
{
    LOGV("glCopyTexImage2D", target, level, internal, x, y, w, h, border);
}
void glCopyTexSubImage1D(GLenum target, GLint level, GLint xo, GLint x, GLint y, GLsizei w)
{
    LOGV("glCopyTexSubImage1D", target, level, xo, x, y, w);
}
void glCopyTexSubImage2D(GLenum target, GLint level, GLint xo, GLint yo, GLint x, GLint y,
                         GLsizei w, GLsizei h)
{
    LOGV("glCopyTexSubImage2D", target, level, xo, yo, x, y, w, h);
}
void glCopyTexSubImage3D(GLenum target, GLint level, GLint xo, GLint yo, GLint zo, GLint x,
                         GLint y, GLsizei w, GLsizei h)
{
    LOGV("glCopyTexSubImage3D", target, level, xo, yo, zo, x, y, w, h);
}
void glTexImage3D(GLenum target, GLint level, GLint internal, GLsizei w, GLsizei h, GLsizei d,
                  GLint border, GLenum format, GLenum type, const GLvoid *pixels)
{
    LOGV("glTexImage3D", target, level, internal, w, h, d, border, format, type);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], pixels);
}
void glTexSubImage3D(GLenum target, GLint level, GLint xo, GLint yo, GLint zo, GLsizei w,
                     GLsizei h, GLsizei d, GLenum format, GLenum type, const GLvoid *pixels)
{
    LOGV("glTexSubImage3D", target, level, xo, yo, zo, w, h, d, format, type);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], pixels);
}

/* ---- Evaluator maps ---------------------------------------------------------------- */

void glMap1f(GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order,
             const GLfloat *points)
{
    LOGV("glMap1f", target, u1, u2, stride, order);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], points);
}
void glMap1d(GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order,
             const GLdouble *points)
{
    LOGV("glMap1d", target, u1, u2, stride, order);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], points);
}
void glMap2f(GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder, GLfloat v1,
             GLfloat v2, GLint vstride, GLint vorder, const GLfloat *points)
{
    LOGV("glMap2f", target, u1, u2, ustride, uorder, v1, v2, vstride, vorder);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], points);
}
void glMap2d(GLenum target, GLdouble u1, GLdouble u2, GLint ustride, GLint uorder, GLdouble v1,
             GLdouble v2, GLint vstride, GLint vorder, const GLdouble *points)
{
    LOGV("glMap2d", target, u1, u2, ustride, uorder, v1, v2, vstride, vorder);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], points);
}
GLint stub_render_mode_result = 0;
GLint glRenderMode(GLenum mode)
{
    LOGV("glRenderMode", mode);
    return stub_render_mode_result;
}
void glSelectBuffer(GLsizei size, GLuint *buffer)
{
    LOGV("glSelectBuffer", size);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], buffer);
}
void glFeedbackBuffer(GLsizei size, GLenum type, GLfloat *buffer)
{
    LOGV("glFeedbackBuffer", size, type);
    arg_p(&stub_log[(stub_nlog - 1) % STUB_LOG_MAX], buffer);
}
void glEnable(GLenum cap) { LOGV("glEnable", cap); }
void glDisable(GLenum cap) { LOGV("glDisable", cap); }
