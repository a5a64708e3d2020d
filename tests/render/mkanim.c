/* mkanim.c: writes the animated test trace (anim.h).
 *
 *   mkanim OUT.raygl FRAMES [WIDTH HEIGHT]
 */
#include <stdio.h>
#include <stdlib.h>

#include "anim.h"

int main(int argc, char **argv)
{
    if (argc != 3 && argc != 5) {
        fprintf(stderr, "usage: mkanim OUT.raygl FRAMES [WIDTH HEIGHT]\n");
        return 2;
    }
    int n = atoi(argv[2]), w = argc == 5 ? atoi(argv[3]) : 160, h = argc == 5 ? atoi(argv[4]) : 120;
    if (n < 1 || n > 100000 || w < 1 || h < 1 || w > 8192 || h > 8192) {
        fprintf(stderr, "mkanim: bad frame count or size\n");
        return 2;
    }
    trace t;
    trace_init(&t);
    for (int i = 0; i < n; i++) {
        seq s;
        seq_init(&s);
        anim_frame(&s, i, n, w, h);
        trace_frame(&t, 0, (uint32_t)i, 0, 0, &s);
        seq_free(&s);
    }
    trace_finish(&t);
    write_file(argv[1], t.data, t.size);
    trace_free(&t);
    return 0;
}
