/* interp_texcopy.c: texture images copied from the framebuffer
 * (glCopyTexImage1D/2D, glCopyTexSubImage1D/2D/3D) and 3D textures
 * (glTexImage3D, glTexSubImage3D).
 *
 * The recorder reads back the rectangle GL copies when the call is made
 * (record/entry_texcopy.c) and records it as 8-bit RGBA, bottom row
 * first: a copy is then glTexImage/glTexSubImage of those pixels, and the
 * texture's internal format keeps what GL keeps of them (GL 2.1 3.8.2: the
 * copied RGBA converted to the base internal format, luminance from red).
 * A copy whose pixels the recorder could not read (no current context, a
 * copy compiled into a list only, a depth copy) defines the image's size
 * with undefined contents, and the frame says the texture is missing.
 *
 * 3D textures keep their level 0, changed by glTexSubImage3D and
 * glCopyTexSubImage3D (one image of it); interp_texture.c draws the slice
 * a primitive's r picks.
 */
#include <stdio.h>

#include "interp_internal.h"

/* Checks what GL checks of a copy before the image (GL 2.1 3.8.2):
 * sizes, level and border; the target and internal format are left to
 * interp_tex_image. */
static bool copy_ok(interp *ip, int64_t w, int64_t h, int64_t level, int64_t border)
{
    if (interp_reject_in_begin(ip))
        return false;
    if (w < 0 || h < 0 || level < 0 || (border != 0 && border != 1)) {
        interp_bad_value(ip, "texture copy size, level or border");
        return false;
    }
    return true;
}

/* The targets GL copies into for dims 1 or 2 (no proxies: GL 2.1 3.8.2);
 * cube-map faces go on to interp_tex_image as glTexImage2D's do. */
static bool copy_target_ok(interp *ip, GLenum target, int dims)
{
    bool face = target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X &&
                target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z;
    bool ok = dims == 1 ? target == GL_TEXTURE_1D
                        : target == GL_TEXTURE_2D || target == GL_TEXTURE_RECTANGLE || face;
    if (!ok)
        interp_bad_enum(ip, "texture copy target", target);
    return ok;
}

/* A copy's pixels that the recorder could not read: the texture drawn
 * from them is missing, and the frame says so. */
static void copy_unread(interp *ip, const char *call, int64_t w, int64_t h)
{
    if (w <= 0 || h <= 0)
        return;
    char what[DIAG_TEXT];
    snprintf(what, sizeof what, "the framebuffer pixels of a %s (not read back when recorded)",
             call);
    interp_missing(ip, what);
}

void interp_copyteximage1d(interp *ip, const rgl_cmd *cmd)
{
    int64_t level = cmd->arg[1].v.i, w = cmd->arg[5].v.i, border = cmd->arg[6].v.i;
    uint32_t id = (uint32_t)cmd->arg[7].v.u;
    if (!copy_target_ok(ip, arg_enum(cmd, 0), 1))
        return;
    if (!copy_ok(ip, w, 1, level, border))
        return;
    interp_unrec_pixel_uses(ip, false, !id, false);
    if (!id)
        copy_unread(ip, "glCopyTexImage1D", w, 1);
    interp_tex_image(ip, arg_enum(cmd, 0), (int32_t)level, (int32_t)cmd->arg[2].v.i, w, 1,
                     (int32_t)border, GL_RGBA, GL_UNSIGNED_BYTE, id);
}

void interp_copyteximage2d(interp *ip, const rgl_cmd *cmd)
{
    int64_t level = cmd->arg[1].v.i, w = cmd->arg[5].v.i, h = cmd->arg[6].v.i;
    int64_t border = cmd->arg[7].v.i;
    uint32_t id = (uint32_t)cmd->arg[8].v.u;
    if (!copy_target_ok(ip, arg_enum(cmd, 0), 2))
        return;
    if (!copy_ok(ip, w, h, level, border))
        return;
    interp_unrec_pixel_uses(ip, false, !id, false);
    if (!id)
        copy_unread(ip, "glCopyTexImage2D", w, h);
    interp_tex_image(ip, arg_enum(cmd, 0), (int32_t)level, (int32_t)cmd->arg[2].v.i, w, h,
                     (int32_t)border, GL_RGBA, GL_UNSIGNED_BYTE, id);
}

void interp_copytexsubimage1d(interp *ip, const rgl_cmd *cmd)
{
    int64_t level = cmd->arg[1].v.i, w = cmd->arg[5].v.i;
    uint32_t id = (uint32_t)cmd->arg[6].v.u;
    if (!copy_target_ok(ip, arg_enum(cmd, 0), 1))
        return;
    if (!copy_ok(ip, w, 1, level, 0))
        return;
    interp_unrec_pixel_uses(ip, false, !id, false);
    if (!id)
        copy_unread(ip, "glCopyTexSubImage1D", w, 1);
    interp_tex_subimage(ip, 1, arg_enum(cmd, 0), level, cmd->arg[2].v.i, 0, w, 1, GL_RGBA,
                        GL_UNSIGNED_BYTE, id);
}

void interp_copytexsubimage2d(interp *ip, const rgl_cmd *cmd)
{
    int64_t level = cmd->arg[1].v.i, w = cmd->arg[6].v.i, h = cmd->arg[7].v.i;
    uint32_t id = (uint32_t)cmd->arg[8].v.u;
    if (!copy_target_ok(ip, arg_enum(cmd, 0), 2))
        return;
    if (!copy_ok(ip, w, h, level, 0))
        return;
    interp_unrec_pixel_uses(ip, false, !id, false);
    if (!id)
        copy_unread(ip, "glCopyTexSubImage2D", w, h);
    interp_tex_subimage(ip, 2, arg_enum(cmd, 0), level, cmd->arg[2].v.i, cmd->arg[3].v.i, w, h,
                        GL_RGBA, GL_UNSIGNED_BYTE, id);
}

/* ---- 3D textures --------------------------------------------------------------------- */

static bool target3d_ok(interp *ip, GLenum target, bool proxy_ok)
{
    if (target == GL_TEXTURE_3D || (proxy_ok && target == GL_PROXY_TEXTURE_3D))
        return true;
    interp_bad_enum(ip, "3D texture target", target);
    return false;
}

static bool size3d_ok(interp *ip, int64_t w, int64_t h, int64_t d, int64_t level)
{
    if (w < 0 || h < 0 || d < 0 || level < 0 || level > 31) {
        interp_bad_value(ip, "3D texture size or level");
        return false;
    }
    return true;
}

void interp_copytexsubimage3d(interp *ip, const rgl_cmd *cmd)
{
    int64_t w = cmd->arg[7].v.i, h = cmd->arg[8].v.i;
    uint32_t id = (uint32_t)cmd->arg[9].v.u;
    if (interp_reject_in_begin(ip) || !target3d_ok(ip, arg_enum(cmd, 0), false) ||
        !size3d_ok(ip, w, h, 1, cmd->arg[1].v.i))
        return;
    interp_unrec_pixel_uses(ip, false, !id, false);
    if (!id)
        copy_unread(ip, "glCopyTexSubImage3D", w, h);
    interp_tex_subimage3d(ip, cmd->arg[1].v.i, cmd->arg[2].v.i, cmd->arg[3].v.i,
                          cmd->arg[4].v.i, w, h, 1, GL_RGBA, GL_UNSIGNED_BYTE, id);
}

void interp_teximage3d(interp *ip, const rgl_cmd *cmd)
{
    GLenum target = arg_enum(cmd, 0);
    if (interp_reject_in_begin(ip) || !target3d_ok(ip, target, true) ||
        !size3d_ok(ip, cmd->arg[3].v.i, cmd->arg[4].v.i, cmd->arg[5].v.i, cmd->arg[1].v.i))
        return;
    int64_t border = cmd->arg[6].v.i;
    if (border != 0 && border != 1) {
        interp_bad_value(ip, "3D texture border");
        return;
    }
    if (target == GL_PROXY_TEXTURE_3D)
        return;
    interp_unrec_pixel_uses(ip, false, false, true);
    interp_tex_image3d(ip, (int32_t)cmd->arg[1].v.i, (int32_t)cmd->arg[2].v.i, cmd->arg[3].v.i,
                       cmd->arg[4].v.i, cmd->arg[5].v.i, (int32_t)border, arg_enum(cmd, 7),
                       arg_enum(cmd, 8), (uint32_t)cmd->arg[9].v.u);
}

void interp_texsubimage3d(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip) || !target3d_ok(ip, arg_enum(cmd, 0), false) ||
        !size3d_ok(ip, cmd->arg[5].v.i, cmd->arg[6].v.i, cmd->arg[7].v.i, cmd->arg[1].v.i))
        return;
    interp_unrec_pixel_uses(ip, false, false, true);
    interp_tex_subimage3d(ip, cmd->arg[1].v.i, cmd->arg[2].v.i, cmd->arg[3].v.i,
                          cmd->arg[4].v.i, cmd->arg[5].v.i, cmd->arg[6].v.i, cmd->arg[7].v.i,
                          arg_enum(cmd, 8), arg_enum(cmd, 9), (uint32_t)cmd->arg[10].v.u);
}
