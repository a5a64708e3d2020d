/* interp_pixmap.c: pixel maps and the pixel transfer of colours (GL 2.1
 * 3.6.3, 3.6.5), as Mesa's pixel.c and pixeltransfer.c hold them:
 * glPixelMap, the scales and biases, GL_MAP_COLOR, and the colour-index
 * pixels of an RGBA context.
 *
 * A colour index (glDrawPixels with GL_COLOR_INDEX) is, in RGBA, looked up
 * in the GL_PIXEL_MAP_I_TO_R, _G, _B and _A maps, masked to their sizes
 * (powers of two). GL 2.1 3.6.5 shifts and offsets it first
 * (GL_INDEX_SHIFT, GL_INDEX_OFFSET); Mesa, the reference, does not on this
 * path, and neither does the translation. RGBA components are then scaled
 * and biased, clamped, and with GL_MAP_COLOR replaced by the R_TO_R ..
 * A_TO_A maps' entry at round(c (size - 1)).
 *
 * That is the translation's. Mesa (22.3, llvmpipe) applies the transfer
 * once in the image tests' programs but twice in others (measured: a red
 * scale of 0.5 took 200 to 50, a blue bias of 0.25 took 100 to 228, and a
 * map 0, 0.2, 0.9, 1 took bytes 0-63 to 0, 64-127 to 0.2, 128-255 to 1,
 * first at floor(c size), then at round(c (size - 1))), and scaled a
 * converted index in one program and not in another: scales, biases and
 * colour maps of pixel rectangles are noted.
 */
#include "interp_internal.h"

/* Map m of GL_PIXEL_MAP_I_TO_I (0) .. GL_PIXEL_MAP_A_TO_A (9). */
#define MAP_I_TO_R 2
#define MAP_R_TO_R 6

void interp_pixelmap(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    GLenum map = arg_enum(cmd, 0);
    int64_t size = cmd->arg[1].v.i;
    const rgl_arg *b = &cmd->arg[2];
    size_t es = cmd->opcode == RGL_OP_PixelMapusv ? 2 : 4;
    if (map < GL_PIXEL_MAP_I_TO_I || map > GL_PIXEL_MAP_A_TO_A) {
        interp_bad_enum(ip, "pixel map", map);
        return;
    }
    bool indexed = map <= GL_PIXEL_MAP_I_TO_A;
    if (size < 1 || size > 256 || (indexed && (size & (size - 1)) != 0)) {
        interp_bad_value(ip, "pixel map size");
        return;
    }
    if (b->count != (size_t)size * es) {
        interp_diag(ip, DIAG_IGNORED, "glPixelMap: %llu bytes for %lld entries",
                    (unsigned long long)b->count, (long long)size);
        return;
    }
    int m = (int)(map - GL_PIXEL_MAP_I_TO_I);
    /* GL 2.1 3.6.3: integer entries of the colour maps are normalised
     * (c / (2^b - 1)); those of I_TO_I and S_TO_S are the values. */
    bool colour = m >= MAP_I_TO_R;
    float *dst = ip->st.a.pixel.map[m];
    for (int64_t i = 0; i < size; i++) {
        const uint8_t *p = b->bytes + (size_t)i * es;
        double v;
        if (es == 2) {
            unsigned u = p[0] | (unsigned)p[1] << 8;
            v = colour ? u / 65535.0 : u;
        } else {
            uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
                         (uint32_t)p[3] << 24;
            if (cmd->opcode == RGL_OP_PixelMapfv) {
                float f;
                memcpy(&f, &u, sizeof f);
                v = isfinite(f) ? f : 0;
            } else {
                v = colour ? u / 4294967295.0 : u;
            }
        }
        /* colour entries clamp to [0, 1] as GL stores them */
        dst[i] = (float)(colour ? (v > 0 ? (v < 1 ? v : 1) : 0) : v);
    }
    ip->st.a.pixel.map_size[m] = (uint16_t)size;
}

static bool transfer_identity(const gl_attribs *a)
{
    for (int k = 0; k < 4; k++)
        if (a->pixel.scale[k] != 1 || a->pixel.bias[k] != 0)
            return false;
    return true;
}

void interp_pixels_transfer_note(interp *ip, bool from_index)
{
    const gl_attribs *a = &ip->st.a;
    /* Scales and biases of RGBA pixels: Mesa's once (pixels_draw,
     * pixels_copy exact). */
    if (a->pixel.map_color || (from_index && !transfer_identity(a)))
        interp_note_pov(ip, DIAG_NOTE_PIXELS_MAP_COLOR, DIAG_COUNT); /* glTF: no pixels */
}

void interp_pixel_transfer(const interp *ip, const float in[4], float out[4])
{
    const gl_attribs *a = &ip->st.a;
    for (int k = 0; k < 4; k++) {
        float c = clamp01(in[k] * a->pixel.scale[k] + a->pixel.bias[k]);
        if (a->pixel.map_color) {
            int m = MAP_R_TO_R + k, size = a->pixel.map_size[m];
            c = a->pixel.map[m][(int)lrintf(c * (float)(size - 1))];
        }
        out[k] = c;
    }
}

static size_t index_type_bytes(GLenum type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT: case GL_SHORT: return 2;
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: return 4;
    default: return 0; /* GL_BITMAP: not translated */
    }
}

size_t interp_pixels_index_bytes(GLenum type, int64_t w, int64_t h)
{
    size_t es = index_type_bytes(type);
    if (!es || w < 0 || h < 0 || (uint64_t)w * (uint64_t)h > ((uint64_t)1 << 26))
        return 0;
    return (size_t)w * (size_t)h * es;
}

void interp_pixels_index(interp *ip, float *px, const uint8_t *src, size_t n, GLenum type)
{
    const gl_attribs *a = &ip->st.a;
    size_t es = index_type_bytes(type);
    for (size_t i = 0; i < n; i++, src += es) {
        uint32_t u = src[0];
        if (es >= 2)
            u |= (uint32_t)src[1] << 8;
        if (es == 4)
            u |= (uint32_t)src[2] << 16 | (uint32_t)src[3] << 24;
        double x;
        switch (type) {
        case GL_BYTE: x = (int8_t)u; break;
        case GL_SHORT: x = (int16_t)u; break;
        case GL_INT: x = (int32_t)u; break;
        case GL_FLOAT: {
            float f;
            memcpy(&f, &u, sizeof f);
            x = isfinite(f) ? f : 0;
            break;
        }
        default: x = u; break;
        }
        /* The integer part of the index indexes the maps. */
        double fl = floor(x);
        int64_t idx = fl < -9e18 ? 0 : fl > 9e18 ? 0 : (int64_t)fl;
        for (int k = 0; k < 4; k++) {
            int m = MAP_I_TO_R + k, size = a->pixel.map_size[m];
            px[i * 4 + k] = a->pixel.map[m][(uint64_t)idx & (uint64_t)(size - 1)];
        }
    }
}
