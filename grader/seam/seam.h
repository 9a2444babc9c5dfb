/* Grader machinery: not part of any assignment. The split suites: a part's tests run twice, in two
 * processes that never share memory, so that no verdict is in the hands of the code under test.
 *
 *   subject-partN  the suite as test-partN links it (tests, framework, every part), with each of
 *                  part N's functions wrapped (ld --wrap): the wrapper calls the real function and
 *                  writes one record of what it returned to a pipe (record.c). Its own verdicts are
 *                  never read: it runs the student's code, so it may lie.
 *   judge-partN    the same tests and framework and the course's other parts, but no code of part N:
 *                  replay.c and seam_partN.c define part N's functions, each of which reads the next
 *                  record, checks it answers this very call (function and a hash of its inputs) and
 *                  reproduces its outputs. The judge runs the assertions, oracles and statistics,
 *                  and its cmocka results are the only ones the grader reads.
 *
 * Both run one test (PL_TEST_FILTER) with the same PL_TEST_SEED, so both make the same calls in the
 * same order; tests call part code from one thread at a time there (pl_test_threads). Only a
 * thread's outermost call is recorded: a part function calling another of its own part is one
 * record. A subject that crashes, exits, stops or sends anything malformed fails the test it was
 * running with a message of the judge's own: the judge never trusts a length, a count or an index.
 *
 * A record: seam_header, then the trace entries (node visits, then primitive tests) the call added
 * to a counters trace the test was recording, then the function's outputs (seam_partN.c). The work
 * counts, the trace and the outputs are the subject's word; the judge checks them only as the test
 * does (the oracles, the work checks of part 2). */
#ifndef PL_SEAM_SPLIT_H
#define PL_SEAM_SPLIT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "../../framework/counters.h"
#include "../../framework/seam.h"
#include "../../framework/bvh.h"
#include "../../framework/ray.h"
#include "../../framework/rng.h"
#include "../../framework/scene.h"

struct render_ctx;

#define SEAM_MAGIC 0x6d616573u       /* "seam" */
#define SEAM_MAX_PAYLOAD (1u << 30)  /* a ceiling for every call; each replay also has its own max */
#define SEAM_MAX_TRACE (1u << 24)    /* trace entries of one call */

/* Part functions, by number: the record names the function it answers. The numbers and names are
 * the seam's one list (framework/seam.h): SEAM_bsdf_f, SEAM_bvh_build, ... */
typedef enum {
#define SEAM_FN_ID(name, task) SEAM_##name,
    PL_SEAM_PART_FUNCTIONS(SEAM_FN_ID)
#undef SEAM_FN_ID
    SEAM_NUM_FUNCTIONS
} seam_fn;

/* The name and handout task of each function (the task a stub reports, framework/todo.h). */
const char *seam_fn_name(int fn);
const char *seam_fn_task(int fn);
/* The function a "Part 3, task 3.4: direct_hemisphere()" text names, or -1. */
int seam_fn_from_todo(const char *text);

typedef struct {
    uint32_t magic;
    uint32_t fn;            /* seam_fn */
    uint64_t inputs;        /* seam_hash of the call's inputs (seam_partN.c) */
    work_counts work;       /* what the call added to the thread's work counters */
    uint32_t todo_calls;    /* stub reports during the call */
    int32_t todo_fn;        /* the function the last of them named, or -1 */
    rng after;              /* the generator after the call (functions that take one), else zeros */
    uint32_t trace_nodes;   /* node visits added to the test's counters trace, ... */
    uint32_t trace_prims;   /* ... and primitive tests, following the header */
    uint32_t trace_overflow;/* the subject's trace ran out of room during the call */
    uint32_t payload;       /* bytes of outputs after the trace */
} seam_header;

/* ---- hashing the inputs: both sides hash the same values the same way -------------------------- */

#define SEAM_HASH_START 0xcbf29ce484222325ull
uint64_t seam_hash(uint64_t h, const void *data, size_t size);
uint64_t seam_hash_int(uint64_t h, int64_t v);
#define SEAM_HASH(h, value) seam_hash((h), &(value), sizeof(value))  /* for structs without padding */
/* The framework's types, field by field (padding holds garbage) and NULL-safe. A scene, a tree and a
 * render context are hashed by their sizes and settings: their arrays are the test's own, the same
 * on both sides, and hashing them on every ray would cost more than the ray. */
uint64_t seam_hash_camera(uint64_t h, const camera *c);
uint64_t seam_hash_ray(uint64_t h, const ray *r);
uint64_t seam_hash_hit(uint64_t h, const hit *x);
uint64_t seam_hash_material(uint64_t h, const material *m);
/* A BSDF's inputs (parts 3, 6 and 7): the material and its two directions; and a BSDF sampler's:
 * the material, wo, the uniform numbers u (NULL for a sampler that takes none) and which of the
 * pointers it fills are given. */
uint64_t seam_hash_bsdf(const material *m, vec3 wo, vec3 wi);
uint64_t seam_hash_bsdf_sample(const material *m, vec3 wo, const vec2 *u, const vec3 *wi, const float *pdf);
uint64_t seam_hash_scene(uint64_t h, const scene *s);
uint64_t seam_hash_bvh(uint64_t h, const bvh *b);
uint64_t seam_hash_ctx(uint64_t h, const struct render_ctx *ctx);
uint64_t seam_hash_rng(uint64_t h, const rng *g);

/* ---- the subject: record.c ------------------------------------------------------------------- */

typedef struct {
    bool outermost;          /* false: a nested call, not recorded */
    work_counts work;        /* counters when the call began */
    int todo;                /* stub reports when it began */
    uint32_t nodes, prims;   /* the test's trace lengths when it began */
    bool overflow;
} seam_call;

/* Begins a call; false for a nested one (the wrapper then just calls the real function). */
bool seam_begin(seam_call *c);
/* Ends an outermost call: writes its record (g: the generator it took, or NULL). The payload is
 * `size` bytes at out, then `extra_size` bytes at extra (a BVH's arrays), or none when NULL. */
void seam_end(seam_call *c, seam_fn fn, uint64_t inputs, const rng *g, const void *out, size_t size,
              const void *const *extra, const size_t *extra_sizes, int num_extra);

/* Intersections (triangles, spheres, the BVH's two queries): the answer, and the ray and hit as the
 * call left them (either may be NULL: not sent, not set). */
typedef struct { unsigned char found; ray r; hit h; } seam_hit_out;  /* a byte: any value read is valid */
void seam_end_hit(seam_call *c, seam_fn fn, uint64_t inputs, bool found, const ray *r, const hit *h);
/* Samplers (a BSDF's or a light's sample_f): the value, and the direction and density they filled
 * (either pointer may be NULL: not sent, not set). Returns f. */
typedef struct { rgb f; vec3 wi; float pdf; } seam_sample_out;
rgb seam_end_sample(seam_call *c, seam_fn fn, uint64_t inputs, rgb f, const vec3 *wi, const float *pdf);

/* ---- the judge: replay.c ---------------------------------------------------------------------- */

/* Reads the record of a call to fn with these inputs, applies its work, trace, stub reports and
 * generator (g may be NULL), and returns its payload (valid until the next replay) with its size in
 * *size. max is the largest payload this call can answer, known to the caller from the function and
 * its inputs: a record claiming more fails before the judge allocates anything. A record that is
 * missing, for another call, larger than max or malformed fails the test (seam_fail). */
const void *seam_replay(seam_fn fn, uint64_t inputs, rng *g, size_t max, size_t *size);
/* seam_replay for a payload of exactly `size` bytes (its max too), copied to out. */
void seam_replay_fixed(seam_fn fn, uint64_t inputs, rng *g, void *out, size_t size);
/* The judge's side of seam_end_hit. */
bool seam_replay_hit(seam_fn fn, uint64_t inputs, ray *r, hit *h);
/* The judge's side of seam_end_sample: fills *wi and *pdf where given, returns f. */
rgb seam_replay_sample(seam_fn fn, uint64_t inputs, vec3 *wi, float *pdf);
/* Trace entries are indices the tests index arrays with: the next replay on this thread accepts node
 * visits below `nodes` and primitive tests below `prims` (the BVH's queries set them from the tree
 * and scene they were given); any other call may add no entry. */
void seam_trace_bounds(int nodes, int prims);
/* Fails the running test with the judge's message about a call to fn: through cmocka on the test's
 * thread; on another (a render's worker) it prints "seam: <message>" and ends the judge with status
 * 3, which the grader reads as that test's failure. Does not return. */
_Noreturn void seam_fail(seam_fn fn, const char *format, ...) __attribute__((format(printf, 2, 3)));

/* ---- one description per part function: its wrapper and its replay ------------------------- */

/* Most part functions answer with their return value alone, or with a hit. For those, one line in
 * seam_partN.c describes the function and these macros write both halves from it: compiled with
 * PL_SEAM_SUBJECT, __wrap_name (ld --wrap sends the tests' calls there), which calls the real
 * function and records what it returned; with PL_SEAM_JUDGE, name itself, which replays the record.
 *
 * SEAM_FIXED(ret, wire, name, params, args, inputs, g): the answer is the return value, sent as
 *   type `wire` (a bool travels as a byte, so any value the judge reads is a valid one). inputs is
 *   an expression over the parameters hashing everything the call depends on; g is the generator
 *   the call takes (its state after the call travels with the answer), or NULL.
 * SEAM_HIT(name, params, args, inputs): an intersection whose parameters are named r (the ray, its
 *   max_t shrunk on a hit) and h (the hit it fills): the answer, the ray and the hit are sent.
 * SEAM_SAMPLER(name, params, args, inputs): a sampler returning rgb whose parameters name the
 *   direction and density it fills wi and pdf: the value and the two are sent (seam_sample_out).
 * Functions with other outputs (pointers they fill, a tree) are written out in their files. */
#if defined(PL_SEAM_SUBJECT)
/* The wrapper both share: hash the inputs, call the real function, record (a nested call is not
 * recorded: seam_begin), return what it returned. */
#define SEAM_WRAPPER(ret, wire, name, params, args, inputs, record)                 \
    ret __real_##name params;                                                       \
    ret __wrap_##name params;                                                       \
    ret __wrap_##name params                                                        \
    {                                                                               \
        seam_call call;                                                             \
        uint64_t in = (inputs);                                                     \
        if (!seam_begin(&call)) return __real_##name args;                          \
        wire out = __real_##name args;                                              \
        record;                                                                     \
        return out;                                                                 \
    }
#define SEAM_FIXED(ret, wire, name, params, args, inputs, g) \
    SEAM_WRAPPER(ret, wire, name, params, args, inputs, seam_end(&call, SEAM_##name, in, (g), &out, sizeof out, NULL, NULL, 0))
#define SEAM_HIT(name, params, args, inputs) \
    SEAM_WRAPPER(bool, bool, name, params, args, inputs, seam_end_hit(&call, SEAM_##name, in, out, r, h))
#define SEAM_SAMPLER(name, params, args, inputs) \
    SEAM_WRAPPER(rgb, rgb, name, params, args, inputs, seam_end_sample(&call, SEAM_##name, in, out, wi, pdf))
#elif defined(PL_SEAM_JUDGE)
#define SEAM_FIXED(ret, wire, name, params, args, inputs, g)                        \
    ret name params                                                                 \
    {                                                                               \
        wire out;                                                                   \
        seam_replay_fixed(SEAM_##name, (inputs), (g), &out, sizeof out);            \
        ret value = out;                                                            \
        return value;                                                               \
    }
#define SEAM_HIT(name, params, args, inputs) \
    bool name params { return seam_replay_hit(SEAM_##name, (inputs), r, h); }
#define SEAM_SAMPLER(name, params, args, inputs) \
    rgb name params { return seam_replay_sample(SEAM_##name, (inputs), wi, pdf); }
#else
#define SEAM_FIXED(ret, wire, name, params, args, inputs, g)
#define SEAM_HIT(name, params, args, inputs)
#define SEAM_SAMPLER(name, params, args, inputs)
#endif

#endif
