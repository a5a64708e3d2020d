/* interp_combine.c: the GL_COMBINE texture environment (GL 1.3, GL 2.1
 * 3.8.13, table 3.20).
 *
 * A unit in GL_COMBINE computes its RGB as a function (REPLACE, MODULATE,
 * ADD, ADD_SIGNED, INTERPOLATE, SUBTRACT, DOT3) of up to three arguments,
 * each a source (TEXTURE, TEXTUREn, CONSTANT, PRIMARY_COLOR, PREVIOUS) taken
 * through an operand (the colour, its alpha, or one minus either), times
 * GL_RGB_SCALE. The common settings are the fixed modes written
 * differently: MODULATE(texture, previous) is GL_MODULATE, REPLACE(texture)
 * GL_REPLACE, ADD(texture, previous) GL_ADD, INTERPOLATE(texture, previous,
 * texture's alpha) GL_DECAL, INTERPOLATE(constant, previous, texture)
 * GL_BLEND. Those take the fixed mode's translation, exact where it is
 * (povwrite_multitex.c chains two units). The rest, a scale other than 1,
 * or an alpha function other than MODULATE or REPLACE, are drawn as
 * GL_MODULATE with a note (the caller's).
 */
#include "interp_internal.h"

#include <string.h>

void interp_combine_defaults(struct gl_texture_unit *t)
{
    t->combine_rgb = t->combine_alpha = GL_MODULATE;
    static const GLenum src[3] = {GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT};
    static const GLenum op[3] = {GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA};
    memcpy(t->combine_src, src, sizeof src);
    memcpy(t->combine_op, op, sizeof op);
    t->rgb_scale = t->alpha_scale = 1;
}

/* GL 2.1 table 3.20's enums for pname, or false when pname is not a
 * combiner parameter. */
bool interp_combine_texenv(interp *ip, GLenum pname, double v)
{
    struct gl_texture_unit *t = &ip->st.a.texture;
    GLenum e = interp_enum_of(v);
    switch (pname) {
    case GL_COMBINE_RGB:
    case GL_COMBINE_ALPHA:
        if (e != GL_REPLACE && e != GL_MODULATE && e != GL_ADD && e != GL_ADD_SIGNED &&
            e != GL_INTERPOLATE && e != GL_SUBTRACT &&
            (pname == GL_COMBINE_ALPHA || (e != GL_DOT3_RGB && e != GL_DOT3_RGBA))) {
            interp_bad_enum(ip, "texture combiner function", e);
            return true;
        }
        *(pname == GL_COMBINE_RGB ? &t->combine_rgb : &t->combine_alpha) = e;
        return true;
    case GL_SOURCE0_RGB: case GL_SOURCE1_RGB: case GL_SOURCE2_RGB:
        if (e != GL_TEXTURE && e != GL_CONSTANT && e != GL_PRIMARY_COLOR && e != GL_PREVIOUS &&
            !(e >= GL_TEXTURE0 && e < GL_TEXTURE0 + INTERP_TEX_UNITS)) {
            interp_bad_enum(ip, "texture combiner source", e);
            return true;
        }
        t->combine_src[pname - GL_SOURCE0_RGB] = e;
        return true;
    case GL_OPERAND0_RGB: case GL_OPERAND1_RGB: case GL_OPERAND2_RGB:
        if (e != GL_SRC_COLOR && e != GL_ONE_MINUS_SRC_COLOR && e != GL_SRC_ALPHA &&
            e != GL_ONE_MINUS_SRC_ALPHA) {
            interp_bad_enum(ip, "texture combiner operand", e);
            return true;
        }
        t->combine_op[pname - GL_OPERAND0_RGB] = e;
        return true;
    case GL_RGB_SCALE:
    case GL_ALPHA_SCALE:
        if (v != 1 && v != 2 && v != 4) {
            interp_bad_value(ip, "texture combiner scale other than 1, 2 or 4");
            return true;
        }
        *(pname == GL_RGB_SCALE ? &t->rgb_scale : &t->alpha_scale) = (float)v;
        return true;
    case GL_SOURCE0_ALPHA: case GL_SOURCE1_ALPHA: case GL_SOURCE2_ALPHA:
    case GL_OPERAND0_ALPHA: case GL_OPERAND1_ALPHA: case GL_OPERAND2_ALPHA:
        return true; /* kept by GL; the alpha function decides below */
    default:
        return false;
    }
}

GLenum interp_combine_mode(const struct gl_texture_unit *t, int unit, bool first)
{
    if (t->rgb_scale != 1 || t->alpha_scale != 1 ||
        (t->combine_alpha != GL_MODULATE && t->combine_alpha != GL_REPLACE))
        return 0;
    /* Which argument is this unit's texel, and which the colour coming in
     * (PREVIOUS; on the first unit also PRIMARY_COLOR, which it equals). */
    bool tex[3], prev[3];
    for (int k = 0; k < 3; k++) {
        GLenum s = t->combine_src[k];
        tex[k] = s == GL_TEXTURE || s == (GLenum)(GL_TEXTURE0 + unit);
        prev[k] = s == GL_PREVIOUS || (first && s == GL_PRIMARY_COLOR);
    }
    const GLenum *op = t->combine_op;
    bool col0 = op[0] == GL_SRC_COLOR, col1 = op[1] == GL_SRC_COLOR;
    switch (t->combine_rgb) {
    case GL_REPLACE:
        return tex[0] && col0 ? GL_REPLACE : 0;
    case GL_MODULATE:
    case GL_ADD:
        if (col0 && col1 && ((tex[0] && prev[1]) || (prev[0] && tex[1])))
            return t->combine_rgb;
        return 0;
    case GL_INTERPOLATE: /* a0 a2 + a1 (1 - a2) */
        if (tex[0] && col0 && prev[1] && col1 && tex[2] && op[2] == GL_SRC_ALPHA)
            return GL_DECAL;
        if (t->combine_src[0] == GL_CONSTANT && col0 && prev[1] && col1 && tex[2] &&
            op[2] == GL_SRC_COLOR)
            return GL_BLEND;
        return 0;
    default:
        return 0;
    }
}
