/* interp_gouraud.c: OpenGL's per-vertex lighting on request
 * (raygl2pov --vertex-lighting; docs/mapping.md "Lights per object,
 * shadows, Gouraud").
 *
 * GL lights each vertex and interpolates the colours (Gouraud); POV-Ray
 * lights each pixel. On finely tessellated surfaces the two agree; on
 * large faces and coarse meshes under point lights, spots or a local
 * viewer they do not (the per-pixel picture is the truer one). With
 * vertex lighting on, a lit filled primitive takes GL's lit colour at each
 * vertex (interp_lit_color, as lit lines and points always do) and is
 * drawn unlit: exactly GL's shading, but emissive, so without shadows or
 * ray-traced highlights. Two-sided lighting, which picks the colour by the
 * face's side, keeps POV-Ray's lighting.
 */
#include "interp_internal.h"

void interp_set_vertex_lighting(interp *ip, bool on) { ip->vertex_lighting = on; }

bool interp_vertex_lit(const interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    return ip->vertex_lighting && a->caps[INTERP_CAP_LIGHTING] && !a->lighting.two_side;
}
