/* Adversary (invented against the known_variance statistic): the render's film comes back on
 * descriptor 3. The code writes a film of its own there first, of the right size and shape (every
 * pixel the case's 16 samples, sums a real set of samples could have) and exits before the framework
 * sends the real one: a flat grey, with a sum of squares of 2^88 in every channel. known_variance
 * (spheres_normals_jitter) took the candidate's own variance where the reference's samples never
 * varied, so the forged spread drowned every block's difference and the grey passed at p = 1. The
 * candidate's variance now counts only up to what one hit in 16 samples weighs against the
 * reference's neighbourhood (grader/verdict.c, pixel_variance): no points.
 * part: 1
 * base: stub
 * replaces: parts/part1_raygen/pixel.c
 * expect: unit=0 images=0
 * other: none
 */
#include "part1.h"
#include "../../framework/todo.h"
#include <stdatomic.h>

/* A six-argument system call tucked into two movabs immediates (see hidden-syscall-exec.c): entered
 * 2 bytes in, mov %rcx, %r10; mov %r9, %rax; a jump over the second opcode; syscall; ret. */
__asm__(".text\n.globl pl_tucked6\n.type pl_tucked6, @function\npl_tucked6:\n"
        "  .byte 0x48, 0xb8, 0x49, 0x89, 0xca, 0x4c, 0x89, 0xc8, 0xeb, 0x02\n"
        "  .byte 0x48, 0xb8, 0x0f, 0x05, 0xc3, 0x90, 0x90, 0x90, 0x90, 0x90\n");
long pl_tucked6(long a, long b, long c, long d, long e, long nr);

static long raw(long nr, long a, long b, long c)
{
    long (*call)(long, long, long, long, long, long) =
        (long (*)(long, long, long, long, long, long))((char *)pl_tucked6 + 2);
    return call(a, b, c, 0, 0, nr);
}

/* The case's film: 160x120 pixels of 136 bytes (framework/output.c: 4 sums and 4 sums of squares
 * of 16 bytes in units of 2^-32, the sample count, the bad-sample count) between header and end. */
#define FILM_W 160
#define FILM_H 120
#define FILM_SAMPLES 16
static unsigned char film[48 + 136 * FILM_W * FILM_H + 8];

static void forge(void)
{
    static const unsigned char head[16] = {'P', 'L', 'F', 'I', 'L', 'M', '1', '\n', FILM_W, 0, 0, 0, FILM_H, 0, 0, 0};
    for (int i = 0; i < 16; i++) film[i] = head[i];
    for (long i = 0; i < (long)FILM_W * FILM_H; i++) {
        unsigned char *p = film + 48 + 136 * i;
        for (int c = 0; c < 4; c++) {
            p[16 * c + 4] = 8;         /* sum: 16 samples of 0.5 = 8, that is 8 * 2^32 */
            p[64 + 16 * c + 15] = 1;   /* sum of squares: 2^120 units, 2^88 */
        }
        p[128] = FILM_SAMPLES;
    }
    static const unsigned char end[8] = {'P', 'L', 'F', 'I', 'L', 'M', '.', '\n'};
    for (int i = 0; i < 8; i++) film[sizeof film - 8 + i] = end[i];
}

ray pixel_sample_ray(const camera *c, int x, int y, int width, int height, vec2 u)
{
    static atomic_int sent;  /* the render's threads all call here: one film, from the first */
    if (atomic_fetch_add(&sent, 1) == 0) {
        forge();
        for (unsigned long at = 0; at < sizeof film;) {  /* a pipe takes what fits: write until all is sent */
            long n = raw(1, 3, (long)(film + at), (long)(sizeof film - at));
            if (n <= 0) break;
            at += (unsigned long)n;
        }
        raw(231, 0, 0, 0);  /* exit_group(0): the framework never sends its film */
    }
    (void)c, (void)x, (void)y, (void)width, (void)height, (void)u;
    return PL_TODO_RAY("1.4", "pixel_sample_ray");
}
