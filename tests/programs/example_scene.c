/* example_scene.c: frame 2 of the README example (examples/example_scene.h, as
 * examples/cube.c draws it in a GLUT window) drawn with OSMesa: the image
 * test checks the lit example against its ray-traced frame, and
 * tools/make-doc-images.sh makes the docs' pictures from it. GL's default
 * infinite viewer (the 95% regime of docs/testing.md).
 */
#include "harness.h"

#include "example_scene.h"

static int draw(int w, int h)
{
    example_draw(2, w, h);
    return 0;
}

RGL_TEST_MAIN(draw)
