/* interp_teximage.h: texture objects and images as the interpreter keeps
 * them, shared by the texture files: interp_texture.c (objects,
 * parameters, environment, copies), interp_teximage.c (the images),
 * interp_texdraw.c (what a draw samples), interp_texslice.c (derived
 * images). Not for other users.
 */
#ifndef RGL_INTERP_TEXIMAGE_H
#define RGL_INTERP_TEXIMAGE_H

#include <stdbool.h>
#include <stdint.h>

#include <GL/gl.h>

#include "interp_internal.h"
#include "namemap.h"

/* 8-bit RGBA texels, bottom row first; shared (refs) between the
 * interpreters that copy a context's state. */
typedef struct tex_image {
    unsigned refs;
    int width, height;
    /* These texels as made or last changed: no two versions of any image
     * share one (0: a temporary image, never looked up by it). Scene
     * textures made from it are found by it (interp_texdraw.c), without
     * a hash of the texels, which a change of a few would have to redo. */
    uint64_t serial;
    uint8_t rgba[]; /* bottom row first */
} tex_image;

/* img's texels are final (made or changed): a new img->serial
 * (interp_teximage.c). */
void interp_tex_image_seal(tex_image *img);

/* Pixels above this per image are refused (an error value, not an attempt
 * to allocate what a hostile trace asks for). 16384 x 16384 RGBA is 1 GiB. */
#define TEX_MAX_TEXELS (1u << 26)

/* Levels 0..14: a 16384-texel side halves to 1 in 14 steps (Mesa's
 * GL_MAX_TEXTURE_LEVELS is 15). */
#define TEX_LEVELS 15

typedef struct tex_obj {
    uint32_t name;
    GLenum target;        /* 0 until first bound */
    GLenum base_format;   /* of level 0 */
    tex_image *img;       /* level 0, or NULL */
    tex_image *lv[TEX_LEVELS]; /* levels 1.., or NULL (lv[0] unused: img) */
    int32_t lw[TEX_LEVELS], lh[TEX_LEVELS]; /* each defined level's size, no border */
    uint32_t levels;      /* bit k: level k defined */
    int32_t base_level, max_level; /* GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL */
    float min_lod, max_lod;        /* GL_TEXTURE_MIN_LOD, GL_TEXTURE_MAX_LOD */
    float lod_bias;                /* GL_TEXTURE_LOD_BIAS */
    bool generate_mipmap;          /* GL_GENERATE_MIPMAP */
    tex_image *face[6];            /* a cube map's level 0: +X, -X, +Y, -Y, +Z, -Z */
    GLenum wrap_s, wrap_t, min_filter, mag_filter;
    GLenum wrap_r;   /* GL_TEXTURE_WRAP_R (3D) */
    int depth3;      /* a 3D texture's images: img holds them one above the
                        other (height = rows x depth3); 0 for 1D and 2D */
    float border[4]; /* GL_TEXTURE_BORDER_COLOR */
    GLenum depth_mode; /* GL_DEPTH_TEXTURE_MODE */
    GLenum compare_mode, compare_func; /* GL_TEXTURE_COMPARE_MODE, _FUNC */
    bool depth;        /* the base level (or level 0) has a depth internal format:
                          every level drawn as depth_mode */
    uint32_t lost;   /* pixels whose damage left the image missing or partly
                        stale (0: none): every frame drawing with it says so */
} tex_obj;

/* GL_MAX_TEXTURE_LOD_BIAS of Mesa (llvmpipe's PIPE_CAPF_MAX_TEXTURE_LOD_BIAS). */
#define TEX_MAX_LOD_BIAS 16.0

struct interp_textures {
    tex_obj *objs; /* named objects, unordered */
    size_t n, cap;
    namemap names; /* name -> index in objs */
    /* object 0 of GL_TEXTURE_1D, GL_TEXTURE_2D, rectangle, 3D, GL_TEXTURE_CUBE_MAP */
    tex_obj zero[5];
    int32_t unpack[8];       /* glPixelStorei values, by pname - GL_UNPACK_SWAP_BYTES */
    /* The scene textures made since the scene last dropped any (a clear,
     * a new frame), by what each was made from: a draw of the same image
     * sampled alike takes its scene texture again without copying texels
     * or charging the frame budget (docs/mapping.md "Bounds";
     * interp_texdraw.c). */
    struct tex_made {
        uint64_t serial; /* the image's (tex_image.serial) */
        uint64_t how;    /* MADE_* and what else the texels depend on */
        double r;        /* a 3D texture's slice: its coordinate */
        int32_t index;   /* in the scene's textures */
    } *made;
    size_t nmade, cap_made;
    const scene *made_sc;
    uint32_t made_gen; /* the scene's generation they belong to */
    /* The range of r over the primitive being drawn, per unit: a 3D
     * texture is drawn as a slice where it is constant. */
    double r_min[INTERP_TEX_UNITS], r_max[INTERP_TEX_UNITS];
    /* Sphere map: the modelview whose inverse transpose is in nrm_mat. */
    mat4 nrm_of, nrm_mat;
    bool nrm_ok;
};

#define ZEROS(t) (sizeof (t)->zero / sizeof (t)->zero[0])

/* Objects (interp_texture.c): the interpreter's texture state, made on
 * first use (NULL: out of memory); the object `name` of target (create:
 * made when missing), or the one bound to target now; the image slot of
 * level k; an image's reference given back. */
interp_textures *interp_tex_state(interp *ip);
tex_obj *interp_tex_get_obj(interp *ip, GLenum target, uint32_t name, bool create);
tex_obj *interp_tex_bound_obj(interp *ip, GLenum target, bool create);
tex_image **interp_tex_level_slot(tex_obj *o, int k);
void interp_tex_image_release(tex_image *img);
/* GL_DEPTH_TEXTURE_MODE of a depth texture: its images redrawn as mode
 * (interp_texture.c). */
void interp_tex_depth_mode(interp *ip, tex_obj *o, GLenum mode);

/* Images (interp_teximage.c): the base format of an internal format (0:
 * not one), and *slot made the interpreter's own copy before a change
 * (NULL: out of memory). */
GLenum interp_tex_base_format(int32_t internal);
tex_image *interp_tex_image_own(interp *ip, tex_image **slot);

/* Whether o is complete (GL 2.1 3.8.10): its levels from the base level
 * up are defined and consistent (interp_texdraw.c). */
bool interp_tex_complete(tex_obj *o);

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
