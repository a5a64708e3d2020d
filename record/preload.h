/* preload.h: the real functions, as libraygl-preload.so calls them.
 *
 * In the preload library the names gl*, glu* and glut* of the calls RayGL
 * records are the recording functions themselves, so the recorder's sources
 * are built with preload_real.h (generated) force-included: each such call
 * goes through rgl_real_fns[index], the function found after this library
 * (dlsym(RTLD_NEXT), or what the program's own lookups returned; preload.c).
 */
#ifndef RGL_PRELOAD_H
#define RGL_PRELOAD_H

typedef void (*rgl_real_fn)(void);

extern rgl_real_fn rgl_real_fns[];

/* Finds the real function of row `index` (preload_real.h's order); never
 * NULL: a function found nowhere is a stub returning 0. */
rgl_real_fn rgl_real_resolve(unsigned index);

/* The calling thread forwards every call unrecorded while inside a real
 * GLU or GLUT call (rgl_tls_passthrough > 0): what they draw is recorded
 * as the shape itself. */
int rgl_guard_enter(void);
void rgl_guard_leave(int *depth);

#define RGL_REAL_PTR(i, name) \
    ((__typeof__(name) *)(rgl_real_fns[i] ? rgl_real_fns[i] : rgl_real_resolve(i)))
#define RGL_REAL_CALL(i, name, ...) (*RGL_REAL_PTR(i, name))(__VA_ARGS__)
#define RGL_REAL_GUARDED(i, name, ...)                                              \
    __extension__({                                                                 \
        int rgl_guard_ __attribute__((cleanup(rgl_guard_leave))) = rgl_guard_enter(); \
        (void)rgl_guard_;                                                           \
        RGL_REAL_CALL(i, name, __VA_ARGS__);                                        \
    })

#endif
