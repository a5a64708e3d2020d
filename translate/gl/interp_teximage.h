/* interp_teximage.h: a texture image as the interpreter keeps it
 * (interp_texture.c), for the sampling helpers of interp_texslice.c.
 */
#ifndef RGL_INTERP_TEXIMAGE_H
#define RGL_INTERP_TEXIMAGE_H

#include <stdbool.h>
#include <stdint.h>

#include <GL/gl.h>

/* 8-bit RGBA texels, bottom row first; shared (refs) between the
 * interpreters that copy a context's state. */
typedef struct tex_image {
    unsigned refs;
    int width, height;
    /* These texels as made or last changed: no two versions of any image
     * share one (0: a temporary image, never looked up by it). Scene
     * textures made from it are found by it (interp_texture.c), without
     * a hash of the texels, which a change of a few would have to redo. */
    uint64_t serial;
    uint8_t rgba[]; /* bottom row first */
} tex_image;

/* Writes img mirrored once along s (ms) and t (mt), the mirror image first,
 * to out: (ms ? 2 : 1) x (mt ? 2 : 1) times the image (mirror clamp). */
void interp_tex_mirror_fill(uint8_t *out, const tex_image *img, bool ms, bool mt);

/* The 2D image of a 3D texture img (depth images of img->height / depth
 * rows, one above the other) at coordinate r: the slice GL_NEAREST picks,
 * or with `linear` the blend of the two around r (GL 2.1 3.8.8), each
 * index wrapped by wrap_r (the clamping modes clamp to the edge slice). A
 * new image with refs 1 (tr_free it), NULL when memory runs out. */
tex_image *interp_tex_slice(const tex_image *img, int depth, double r, bool linear,
                            GLenum wrap_r);

#endif
