/* raygl.h: the RayGL recording API.
 *
 * Every supported OpenGL 1.x, GLU and GLUT call has a twin with the same
 * signature, named with `ray` in front (rayglVertex3f, raygluSphere,
 * rayglutSolidTeapot). A twin records the call into the calling thread's
 * stream and then makes the real call, so the window looks as before. A frame
 * ends at rayglutSwapBuffers() or rayglFrameEnd(); the frame is then on disk.
 *
 * Recording starts at the first call, into the file named by RAYGL_TRACE, or
 * <program>.raygl in the working directory when it is unset (<program>.1.raygl,
 * .2, ... when that exists). RAYGL_RECORD=0 turns recording off. The functions
 * below choose the file and query the recorder from the program instead.
 *
 * The prototypes of most twins are generated from the command table
 * (commands.def); the hand-written ones follow. Every other GL 1.0-2.1, GLU
 * and freeglut call has a twin too, in raygl/unrecorded.h: it is counted
 * (the trace says per frame what was not recorded), not recorded.
 */
#ifndef RAYGL_H
#define RAYGL_H

#include <GL/gl.h>
#include <GL/glu.h>

#include "cmdtable.h"

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__)
#define RAYGL_API __attribute__((visibility("default")))
#else
#define RAYGL_API
#endif

/* ---- Recorder control ---------------------------------------------------- */

enum raygl_record_status {
    RAYGL_IDLE = 0,      /* no trace open yet (opens at the first call) */
    RAYGL_RECORDING = 1, /* recording into rayglRecordPath() */
    RAYGL_FAILED = 2,    /* an I/O or memory failure stopped recording */
    RAYGL_DISABLED = 3,  /* RAYGL_RECORD=0, closed, or a forked child */
};

/* Closes any open trace and starts a new one at path (NULL: the default
 * name). Returns 0, or -1 with errno set; the program goes on either way. */
RAYGL_API int rayglRecordOpen(const char *path);

/* Ends every thread's frame in progress, writes the index and closes the
 * trace. Later calls are forwarded to GL but not recorded. Also runs at exit. */
RAYGL_API void rayglRecordClose(void);

/* One of enum raygl_record_status. */
RAYGL_API int rayglRecordStatus(void);

/* The path of the trace, or NULL before it is opened. */
RAYGL_API const char *rayglRecordPath(void);

/* A one-line description of the failure that stopped recording, or NULL. */
RAYGL_API const char *rayglRecordError(void);

/* Frame snapshots: with enable non-zero, every frame from the next frame
 * end on also stores the image the program showed (its viewport, read back
 * before the swap, compressed), for `raygl-compare`. The default is the
 * RAYGL_SNAPSHOTS environment variable (1: on). Costs a glReadPixels and a
 * deflate per frame. */
RAYGL_API void rayglRecordSnapshots(int enable);

/* Where the failure message goes: by default one line on stderr. A NULL
 * handler silences it. The handler runs at most once, on the failing thread. */
RAYGL_API void rayglRecordSetErrorHandler(void (*handler)(const char *message, void *user),
                                          void *user);

/* ---- The paper's frame calls --------------------------------------------- */

/* Starts a frame that raygl2pov writes as `file` (inside its output folder),
 * with a camera at loc looking at look and a white parallel light at light. */
RAYGL_API void rayglFrameBegin(const char *file, GLfloat locx, GLfloat locy, GLfloat locz,
                               GLfloat lookx, GLfloat looky, GLfloat lookz, GLfloat lightx,
                               GLfloat lighty, GLfloat lightz);
/* Ends the frame: it is written to the trace before this returns. */
RAYGL_API void rayglFrameEnd(void);

/* ---- Twins generated from the command table -------------------------------- */

#define RGL_CTYPE_b GLbyte
#define RGL_CTYPE_ub GLubyte
#define RGL_CTYPE_s GLshort
#define RGL_CTYPE_us GLushort
#define RGL_CTYPE_i GLint
#define RGL_CTYPE_ui GLuint
#define RGL_CTYPE_f GLfloat
#define RGL_CTYPE_d GLdouble
#define RGL_CTYPE_e GLenum
#define RGL_CTYPE_bf GLbitfield
#define RGL_CTYPE_bo GLboolean
#define RGL_CTYPE_sz GLsizei

#define RGL_PROTO_P(t, n) RGL_CTYPE_##t n
#define RGL_PROTO_A(t, n, c) const RGL_CTYPE_##t *n
#define RGL_PROTO_N(t, n, c) const RGL_CTYPE_##t *n
#define RGL_PROTO_STR(n) const char *n
#define RGL_PROTO_NOARGS void

#define RGL_PROTO_GEN_AUTO(api, name, ...) \
    RAYGL_API void RGL_APIFN(api, name)(RGL_MAP_LIST(RGL_PROTO_, __VA_ARGS__));
#define RGL_PROTO_GEN_PRIM RGL_PROTO_GEN_AUTO
#define RGL_PROTO_GEN_CUSTOM(api, name, ...)
#define RGL_PROTO_GEN_WIRE(api, name, ...)
#define RGL_CMD(op, api, gen, name, handler, ...) RGL_PROTO_GEN_##gen(api, name, __VA_ARGS__)
#include "commands.def"
#undef RGL_CMD

/* ---- Hand-written twins (rows marked CUSTOM in the table) ------------------ */

RAYGL_API void rayglArrayElement(GLint i);
RAYGL_API void rayglDrawArrays(GLenum mode, GLint first, GLsizei count);
RAYGL_API void rayglDrawElements(GLenum mode, GLsizei count, GLenum type, const GLvoid *indices);
RAYGL_API void rayglDrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count,
                                      GLenum type, const GLvoid *indices);
RAYGL_API void rayglGenTextures(GLsizei n, GLuint *textures);
RAYGL_API void rayglDeleteTextures(GLsizei n, const GLuint *textures);
RAYGL_API void rayglBindTexture(GLenum target, GLuint texture);
RAYGL_API void rayglPixelStorei(GLenum pname, GLint param);
RAYGL_API void rayglTexImage1D(GLenum target, GLint level, GLint internalFormat, GLsizei width,
                               GLint border, GLenum format, GLenum type, const GLvoid *pixels);
RAYGL_API void rayglTexImage2D(GLenum target, GLint level, GLint internalFormat, GLsizei width,
                               GLsizei height, GLint border, GLenum format, GLenum type,
                               const GLvoid *pixels);
RAYGL_API void rayglTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                  GLsizei width, GLsizei height, GLenum format, GLenum type,
                                  const GLvoid *pixels);
RAYGL_API void rayglTexParameterf(GLenum target, GLenum pname, GLfloat param);
RAYGL_API void rayglTexParameterfv(GLenum target, GLenum pname, const GLfloat *params);
RAYGL_API void rayglTexParameteri(GLenum target, GLenum pname, GLint param);
RAYGL_API void rayglTexParameteriv(GLenum target, GLenum pname, const GLint *params);
RAYGL_API GLuint rayglGenLists(GLsizei range);
RAYGL_API void rayglNewList(GLuint list, GLenum mode);
RAYGL_API void rayglEndList(void);
RAYGL_API void rayglCallLists(GLsizei n, GLenum type, const GLvoid *lists);
RAYGL_API void rayglDeleteLists(GLuint list, GLsizei range);
RAYGL_API void rayglVertexPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr);
RAYGL_API void rayglNormalPointer(GLenum type, GLsizei stride, const GLvoid *ptr);
RAYGL_API void rayglColorPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr);
RAYGL_API void rayglTexCoordPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *ptr);
RAYGL_API void rayglEdgeFlagPointer(GLsizei stride, const GLvoid *ptr);
/* The fog-coordinate and secondary-colour arrays (GL 1.4 and EXT names). */
RAYGL_API void rayglFogCoordPointer(GLenum type, GLsizei stride, const GLvoid *ptr);
RAYGL_API void rayglFogCoordPointerEXT(GLenum type, GLsizei stride, const GLvoid *ptr);
RAYGL_API void rayglSecondaryColorPointer(GLint size, GLenum type, GLsizei stride,
                                          const GLvoid *ptr);
RAYGL_API void rayglSecondaryColorPointerEXT(GLint size, GLenum type, GLsizei stride,
                                             const GLvoid *ptr);
RAYGL_API void rayglInterleavedArrays(GLenum format, GLsizei stride, const GLvoid *pointer);
RAYGL_API void rayglEnableClientState(GLenum array);
RAYGL_API void rayglDisableClientState(GLenum array);
/* The unit whose texture-coordinate array the calls above change (GL 1.3,
 * ARB_multitexture). */
RAYGL_API void rayglClientActiveTexture(GLenum texture);
RAYGL_API void rayglClientActiveTextureARB(GLenum texture);
RAYGL_API void rayglMultiDrawArrays(GLenum mode, const GLint *first, const GLsizei *count,
                                    GLsizei drawcount);
RAYGL_API void rayglMultiDrawElements(GLenum mode, const GLsizei *count, GLenum type,
                                      const void *const *indices, GLsizei drawcount);
/* The EXT names of the array draws, recorded as rows of their own. */
RAYGL_API void rayglArrayElementEXT(GLint i);
RAYGL_API void rayglDrawArraysEXT(GLenum mode, GLint first, GLsizei count);
RAYGL_API void rayglDrawRangeElementsEXT(GLenum mode, GLuint start, GLuint end, GLsizei count,
                                         GLenum type, const void *indices);
RAYGL_API void rayglMultiDrawArraysEXT(GLenum mode, const GLint *first, const GLsizei *count,
                                       GLsizei primcount);
RAYGL_API void rayglMultiDrawElementsEXT(GLenum mode, const GLsizei *count, GLenum type,
                                         const void *const *indices, GLsizei primcount);

/* Buffer objects (GL 1.5) and their ARB_vertex_buffer_object names. */
RAYGL_API void rayglGenBuffers(GLsizei n, GLuint *buffers);
RAYGL_API void rayglDeleteBuffers(GLsizei n, const GLuint *buffers);
RAYGL_API void rayglBindBuffer(GLenum target, GLuint buffer);
RAYGL_API void rayglBufferData(GLenum target, GLsizeiptr size, const void *data, GLenum usage);
RAYGL_API void rayglBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size,
                                  const void *data);
RAYGL_API void *rayglMapBuffer(GLenum target, GLenum access);
RAYGL_API GLboolean rayglUnmapBuffer(GLenum target);
RAYGL_API void rayglGenBuffersARB(GLsizei n, GLuint *buffers);
RAYGL_API void rayglDeleteBuffersARB(GLsizei n, const GLuint *buffers);
RAYGL_API void rayglBindBufferARB(GLenum target, GLuint buffer);
RAYGL_API void rayglBufferDataARB(GLenum target, GLsizeiptrARB size, const void *data,
                                  GLenum usage);
RAYGL_API void rayglBufferSubDataARB(GLenum target, GLintptrARB offset, GLsizeiptrARB size,
                                     const void *data);
RAYGL_API void *rayglMapBufferARB(GLenum target, GLenum access);
RAYGL_API GLboolean rayglUnmapBufferARB(GLenum target);

/* Evaluator maps: the control points GL reads, copied into the record. */
RAYGL_API void rayglMap1f(GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order,
                          const GLfloat *points);
RAYGL_API void rayglMap1d(GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order,
                          const GLdouble *points);
RAYGL_API void rayglMap2f(GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder,
                          GLfloat v1, GLfloat v2, GLint vstride, GLint vorder,
                          const GLfloat *points);
RAYGL_API void rayglMap2d(GLenum target, GLdouble u1, GLdouble u2, GLint ustride, GLint uorder,
                          GLdouble v1, GLdouble v2, GLint vstride, GLint vorder,
                          const GLdouble *points);

/* Pixel rectangles: the bits and pixels GL reads, as a resource;
 * glCopyPixels' source read back from the framebuffer at the call. */
RAYGL_API void rayglBitmap(GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig,
                           GLfloat xmove, GLfloat ymove, const GLubyte *bitmap);
RAYGL_API void rayglDrawPixels(GLsizei width, GLsizei height, GLenum format, GLenum type,
                               const GLvoid *pixels);
RAYGL_API void rayglCopyPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum type);
/* The polygon stipple: its 32 x 32 mask read as glBitmap's bits. */
RAYGL_API void rayglPolygonStipple(const GLubyte *mask);
/* The pixel maps: the mapsize values GL reads (client memory or the
 * unpack buffer), where GL takes the map. */
RAYGL_API void rayglPixelMapfv(GLenum map, GLsizei mapsize, const GLfloat *values);
RAYGL_API void rayglPixelMapuiv(GLenum map, GLsizei mapsize, const GLuint *values);
RAYGL_API void rayglPixelMapusv(GLenum map, GLsizei mapsize, const GLushort *values);
/* The draw buffer, with the context's colour buffers (double-buffered,
 * stereo) as found at the call. */
RAYGL_API void rayglDrawBuffer(GLenum mode);

/* Texture copies, their framebuffer rectangle read back at the call; 3D
 * textures, their pixels read as glTexImage2D's (unpack image height and
 * skipped images included). */
RAYGL_API void rayglCopyTexImage1D(GLenum target, GLint level, GLenum internalformat, GLint x,
                                   GLint y, GLsizei width, GLint border);
RAYGL_API void rayglCopyTexImage2D(GLenum target, GLint level, GLenum internalformat, GLint x,
                                   GLint y, GLsizei width, GLsizei height, GLint border);
RAYGL_API void rayglCopyTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLint x, GLint y,
                                      GLsizei width);
RAYGL_API void rayglCopyTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                      GLint x, GLint y, GLsizei width, GLsizei height);
RAYGL_API void rayglCopyTexSubImage3D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                      GLint zoffset, GLint x, GLint y, GLsizei width,
                                      GLsizei height);
RAYGL_API void rayglTexImage3D(GLenum target, GLint level, GLint internalFormat, GLsizei width,
                               GLsizei height, GLsizei depth, GLint border, GLenum format,
                               GLenum type, const GLvoid *pixels);
RAYGL_API void rayglTexSubImage3D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                  GLint zoffset, GLsizei width, GLsizei height, GLsizei depth,
                                  GLenum format, GLenum type, const GLvoid *pixels);
/* Their EXT names (and glBindTextureEXT, glTexSubImage2DEXT), recorded as
 * rows of their own, with glext.h's prototypes. */
RAYGL_API void rayglCopyTexImage1DEXT(GLenum target, GLint level, GLenum internalformat, GLint x,
                                      GLint y, GLsizei width, GLint border);
RAYGL_API void rayglCopyTexImage2DEXT(GLenum target, GLint level, GLenum internalformat, GLint x,
                                      GLint y, GLsizei width, GLsizei height, GLint border);
RAYGL_API void rayglCopyTexSubImage1DEXT(GLenum target, GLint level, GLint xoffset, GLint x,
                                         GLint y, GLsizei width);
RAYGL_API void rayglCopyTexSubImage2DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                         GLint x, GLint y, GLsizei width, GLsizei height);
RAYGL_API void rayglCopyTexSubImage3DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                         GLint zoffset, GLint x, GLint y, GLsizei width,
                                         GLsizei height);
RAYGL_API void rayglTexImage3DEXT(GLenum target, GLint level, GLenum internalformat, GLsizei width,
                                  GLsizei height, GLsizei depth, GLint border, GLenum format,
                                  GLenum type, const void *pixels);
RAYGL_API void rayglTexSubImage3DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                     GLint zoffset, GLsizei width, GLsizei height, GLsizei depth,
                                     GLenum format, GLenum type, const void *pixels);
RAYGL_API void rayglBindTextureEXT(GLenum target, GLuint texture);
RAYGL_API void rayglTexSubImage2DEXT(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                     GLsizei width, GLsizei height, GLenum format, GLenum type,
                                     const void *pixels);

/* glEnable / glDisable: the client arrays (GL_VERTEX_ARRAY, ...), which
 * Mesa takes there as glEnableClientState does, are recorded as that. */
RAYGL_API void rayglEnable(GLenum cap);
RAYGL_API void rayglDisable(GLenum cap);

/* Render modes: glRenderMode returns GL's answer; the buffers are GL's to
 * write and never read by RayGL. */
RAYGL_API GLint rayglRenderMode(GLenum mode);
RAYGL_API void rayglSelectBuffer(GLsizei size, GLuint *buffer);
RAYGL_API void rayglFeedbackBuffer(GLsizei size, GLenum type, GLfloat *buffer);

RAYGL_API GLUquadric *raygluNewQuadric(void);
RAYGL_API void raygluDeleteQuadric(GLUquadric *quad);
RAYGL_API void raygluQuadricDrawStyle(GLUquadric *quad, GLenum draw);
RAYGL_API void raygluQuadricNormals(GLUquadric *quad, GLenum normal);
RAYGL_API void raygluQuadricOrientation(GLUquadric *quad, GLenum orientation);
RAYGL_API void raygluQuadricTexture(GLUquadric *quad, GLboolean texture);
RAYGL_API void raygluSphere(GLUquadric *quad, GLdouble radius, GLint slices, GLint stacks);
RAYGL_API void raygluCylinder(GLUquadric *quad, GLdouble base, GLdouble top, GLdouble height,
                              GLint slices, GLint stacks);
RAYGL_API void raygluDisk(GLUquadric *quad, GLdouble inner, GLdouble outer, GLint slices,
                          GLint loops);
RAYGL_API void raygluPartialDisk(GLUquadric *quad, GLdouble inner, GLdouble outer, GLint slices,
                                 GLint loops, GLdouble start, GLdouble sweep);
RAYGL_API GLint raygluBuild2DMipmaps(GLenum target, GLint internalFormat, GLsizei width,
                                     GLsizei height, GLenum format, GLenum type, const void *data);

/* GLU NURBS: the calls recorded as such (GLU draws them at gluEndSurface
 * and gluEndCurve; its own GL calls are not recorded). */
RAYGL_API GLUnurbs *raygluNewNurbsRenderer(void);
RAYGL_API void raygluDeleteNurbsRenderer(GLUnurbs *nurb);
RAYGL_API void raygluNurbsProperty(GLUnurbs *nurb, GLenum property, GLfloat value);
RAYGL_API void raygluLoadSamplingMatrices(GLUnurbs *nurb, const GLfloat *model,
                                          const GLfloat *perspective, const GLint *view);
RAYGL_API void raygluBeginSurface(GLUnurbs *nurb);
RAYGL_API void raygluEndSurface(GLUnurbs *nurb);
RAYGL_API void raygluNurbsSurface(GLUnurbs *nurb, GLint sKnotCount, GLfloat *sKnots,
                                  GLint tKnotCount, GLfloat *tKnots, GLint sStride, GLint tStride,
                                  GLfloat *control, GLint sOrder, GLint tOrder, GLenum type);
RAYGL_API void raygluBeginCurve(GLUnurbs *nurb);
RAYGL_API void raygluEndCurve(GLUnurbs *nurb);
RAYGL_API void raygluNurbsCurve(GLUnurbs *nurb, GLint knotCount, GLfloat *knots, GLint stride,
                                GLfloat *control, GLint order, GLenum type);
RAYGL_API void raygluBeginTrim(GLUnurbs *nurb);
RAYGL_API void raygluEndTrim(GLUnurbs *nurb);
RAYGL_API void raygluPwlCurve(GLUnurbs *nurb, GLint count, GLfloat *data, GLint stride,
                              GLenum type);

RAYGL_API void rayglutSwapBuffers(void);

#ifdef __cplusplus
}
#endif

#endif
