/* interp_texpacked.c: GL's packed pixel types (GL 1.2, GL 2.1 table 3.8
 * and figures 3.6-3.8): the components of one pixel packed into a byte,
 * a short or an int, in component order from the most significant bits,
 * or from the least for the _REV types. The components are then placed
 * by the format as unpacked ones are (GL_BGRA's first component is blue).
 * Used by interp_texture.c for texture images and pixel rectangles.
 */
#include "interp_internal.h"

typedef struct packed_type {
    GLenum type;
    uint8_t bytes, comps;
    bool rev;
    uint8_t bits[4]; /* in component order */
} packed_type;

static const packed_type packed_types[] = {
    {GL_UNSIGNED_BYTE_3_3_2, 1, 3, false, {3, 3, 2, 0}},
    {GL_UNSIGNED_BYTE_2_3_3_REV, 1, 3, true, {3, 3, 2, 0}},
    {GL_UNSIGNED_SHORT_5_6_5, 2, 3, false, {5, 6, 5, 0}},
    {GL_UNSIGNED_SHORT_5_6_5_REV, 2, 3, true, {5, 6, 5, 0}},
    {GL_UNSIGNED_SHORT_4_4_4_4, 2, 4, false, {4, 4, 4, 4}},
    {GL_UNSIGNED_SHORT_4_4_4_4_REV, 2, 4, true, {4, 4, 4, 4}},
    {GL_UNSIGNED_SHORT_5_5_5_1, 2, 4, false, {5, 5, 5, 1}},
    {GL_UNSIGNED_SHORT_1_5_5_5_REV, 2, 4, true, {5, 5, 5, 1}},
    {GL_UNSIGNED_INT_8_8_8_8, 4, 4, false, {8, 8, 8, 8}},
    {GL_UNSIGNED_INT_8_8_8_8_REV, 4, 4, true, {8, 8, 8, 8}},
    {GL_UNSIGNED_INT_10_10_10_2, 4, 4, false, {10, 10, 10, 2}},
    {GL_UNSIGNED_INT_2_10_10_10_REV, 4, 4, true, {10, 10, 10, 2}},
};

static const packed_type *find(GLenum type)
{
    for (size_t k = 0; k < sizeof packed_types / sizeof packed_types[0]; k++)
        if (packed_types[k].type == type)
            return &packed_types[k];
    return NULL;
}

int interp_packed_layout(GLenum type, size_t *bytes)
{
    const packed_type *t = find(type);
    if (!t)
        return 0;
    *bytes = t->bytes;
    return t->comps;
}

void interp_packed_decode(const uint8_t *p, GLenum type, float out[4])
{
    const packed_type *t = find(type);
    if (!t)
        return;
    uint32_t v = 0;
    for (unsigned k = 0; k < t->bytes; k++) /* the trace's bytes are little-endian */
        v |= (uint32_t)p[k] << (8 * k);
    unsigned shift = t->rev ? 0 : 8u * t->bytes;
    for (unsigned k = 0; k < t->comps; k++) {
        unsigned b = t->bits[k];
        if (!t->rev)
            shift -= b;
        uint32_t max = (1u << b) - 1;
        out[k] = (float)((v >> shift) & max) / (float)max;
        if (t->rev)
            shift += b;
    }
}
