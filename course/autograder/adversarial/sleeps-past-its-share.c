/* Adversary (issue 46): part 1, whose ray generation sleeps (using no CPU) far past its share of the
 * grading's time; before, a stall like it (a blocking #include in each of 32 files, compiled on after
 * a failure) ran every part past the autograder's own limit, and every part scored 0. Now the grading
 * has one deadline, within the autograder's: each part gets its share of what is left, every stage's
 * limit is the least of its own and what is left, and a part that runs out says so and keeps what
 * finished. Part 3, graded after it, keeps its full marks.
 * part: 1
 * base: solution
 * replaces: parts/part1_raygen/camera_ray.c
 * expect: unit=lost images=0
 * timeout: 240
 * present: the grading ran out of time
 */
#include "part1.h"

/* nanosleep is on no list a part may call: the system call itself, which the sandbox's filter allows
 * (a sleep harms nobody), made inline where the machine is x86-64, else a spin. */
static void sleep_long(void)
{
#if defined(__x86_64__)
    struct { long seconds, nanoseconds; } forever = {100000, 0};
    long ret;
    __asm__ volatile("syscall" : "=a"(ret) : "a"(35L), "D"(&forever), "S"(0L) : "rcx", "r11", "memory");
    (void)ret;
#else
    for (volatile long spin = 1; spin;) continue;
#endif
}

ray camera_generate_ray(const camera *c, float x, float y)
{
    sleep_long();
    (void)c, (void)x, (void)y;
    return (ray){{0, 0, 0}, {0, 0, -1}, 0.0f, 1e30f};
}
