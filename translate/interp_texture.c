/* interp_texture.c: texture objects, texture environment, texture
 * coordinate generation (issue 5). */
#include "interp_internal.h"

void interp_gentextures(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_deletetextures(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_teximage1d(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_teximage2d(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_texsubimage2d(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_texparameter(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_texgen(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_pixelstore(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_build2dmipmaps(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }

void interp_bindtexture(interp *ip, const rgl_cmd *cmd)
{
    GLenum target = arg_enum(cmd, 0);
    uint32_t name = (uint32_t)cmd->arg[1].v.u;
    if (target == GL_TEXTURE_1D)
        ip->st.a.texture.binding_1d = name;
    else if (target == GL_TEXTURE_2D)
        ip->st.a.texture.binding_2d = name;
}

void interp_texenv(interp *ip, const rgl_cmd *cmd)
{
    GLenum pname = arg_enum(cmd, 1);
    if (pname == GL_TEXTURE_ENV_MODE && cmd->arg[2].kind == RGL_ARG_SCALAR)
        ip->st.a.texture.env_mode = (GLenum)arg_num(&cmd->arg[2]);
}


int interp_textures_copy(interp *dst, const interp *src) { (void)dst; (void)src; return 0; }
void interp_textures_free(interp *ip) { (void)ip; }
int32_t interp_texture_for_draw(interp *ip) { (void)ip; return -1; }

void interp_vertex_texcoord(interp *ip, const double obj[4], const float nrm[3], float out[2])
{
    (void)obj;
    (void)nrm;
    const float *tc = ip->st.a.current.texcoord;
    out[0] = tc[0];
    out[1] = tc[1];
}
