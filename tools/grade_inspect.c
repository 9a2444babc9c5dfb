/* Grader machinery: not part of any assignment.
 * The link-time allow-list (DESIGN.md section 9): before any of a submission's code runs, the
 * objects the build made from its part, the very files linked into bin/pathtracer and the test
 * suite (graded trees build without link-time optimisation, so they hold machine code), are read:
 * - every undefined symbol must be a part's own function or another part's, or on the allow-list
 *   (grade_allow.c: a narrow framework API, libm, memory, sorting and printing from libc);
 * - no constructors or destructors (.init_array, .fini_array, .ctors, .dtors, .preinit_array): code
 *   that runs before main could act before the grader's checks;
 * - no system call instruction in the machine code (inline assembly around the list).
 * The first violation is reported naming the file and the symbol; the part then scores zero. */
#include "grade_inspect.h"
#include "grade.h"
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define INSPECT_SECONDS 120
#define LOG_MAX (4 << 20)
#define OBJ_DIR "build/release"  /* where the Makefile puts a release build's objects */

static bool run_to(char *const argv[], const char *cwd, const char *log, bool untrusted)
{
    grade_run_opts o = {INSPECT_SECONDS, cwd, log, LOG_MAX, NULL, untrusted};
    grade_run_result r = grade_run(argv, &o);
    return r.exited && r.status == 0;
}

/* The functions the parts define, the submission's own files included: a part may call its own
 * functions, whatever their names, and the other parts' (the framework's are on the allow-list). */
static char *defined_symbols(const char *tree, const char *log)
{
    char cmd[8192];
    snprintf(cmd, sizeof cmd,
             "cd '%s' && for o in " OBJ_DIR "/parts/*/*.o; do "
             "gcc-nm --defined-only --format=just-symbols \"$o\"; done", tree);
    char *argv[] = {"sh", "-c", cmd, NULL};
    if (!run_to(argv, NULL, log, false)) return NULL;
    FILE *f = fopen(log, "r");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    rewind(f);
    char *text = malloc((size_t)size + 3);
    if (text) {
        text[0] = '\n';
        size_t got = fread(text + 1, 1, (size_t)size, f);
        text[got + 1] = '\n';
        text[got + 2] = '\0';
    }
    fclose(f);
    return text;
}

static bool defined_in(const char *symbols, const char *name)
{
    char needle[300];
    snprintf(needle, sizeof needle, "\n%s\n", name);
    return strstr(symbols, needle) != NULL;
}

/* Scans one tool's output (in log) line by line for a violation; fills why on the first. */
typedef bool (*line_check)(const char *line, const char *symbols, char *why, size_t size);

static bool scan(const char *log, line_check check, const char *symbols, char *why, size_t size)
{
    FILE *f = fopen(log, "r");
    if (!f) return false;
    char line[1024];
    bool bad = false;
    while (!bad && fgets(line, sizeof line, f)) {
        line[strcspn(line, "\r\n")] = '\0';
        bad = check(line, symbols, why, size);
    }
    fclose(f);
    return bad;
}

static bool bad_symbol(const char *line, const char *symbols, char *why, size_t size)
{
    const char *name = line;
    while (*name == ' ') name++;
    if (!*name || defined_in(symbols, name) || grade_allowed_symbol(name)) return false;
    snprintf(why, size, "calls `%s`, which part code may not use (handout/README.md, \"What your part may "
                        "call\", lists what it may)", name);
    return true;
}

static bool bad_section(const char *line, const char *symbols, char *why, size_t size)
{
    (void)symbols;
    static const char *const sections[] = {".init_array", ".fini_array", ".preinit_array", ".ctors", ".dtors", NULL};
    for (const char *const *s = sections; *s; s++)
        if (strstr(line, *s)) {
            snprintf(why, size, "has a constructor or destructor (section %s): code may not run outside its tasks", *s);
            return true;
        }
    return false;
}

static bool bad_instruction(const char *line, const char *symbols, char *why, size_t size)
{
    (void)symbols;
    /* objdump -d prints "syscall", "sysenter" or "int $0x80" as the mnemonic column. */
    if (strstr(line, "\tsyscall") || strstr(line, "\tsysenter") || strstr(line, "\tint    $0x80")) {
        snprintf(why, size, "contains a system call instruction: part code may not talk to the kernel");
        return true;
    }
    return false;
}

bool grade_inspect_part(const char *tree, const char *folder, const char *work, bool untrusted, char *why,
                        size_t size)
{
    char log[4200], src_dir[4200];
    snprintf(src_dir, sizeof src_dir, "%s/parts/%s", tree, folder);
    snprintf(log, sizeof log, "%s/inspect-symbols.txt", work);
    char *symbols = defined_symbols(tree, log);
    if (!symbols) return snprintf(why, size, "cannot list the parts' symbols"), false;

    /* Each .c of the part has its object, made by the build with the build's own flags. */
    bool ok = true;
    DIR *d = opendir(src_dir);
    if (!d) ok = snprintf(why, size, "cannot read parts/%s", folder) < 0;
    for (struct dirent *e; ok && d && (e = readdir(d));) {
        size_t n = strlen(e->d_name);
        if (n < 3 || strcmp(e->d_name + n - 2, ".c")) continue;
        char obj[4400], tool_log[4400], what[512] = "";
        struct stat st;
        snprintf(obj, sizeof obj, "%s/" OBJ_DIR "/parts/%s/%.*s.o", tree, folder, (int)n - 2, e->d_name);
        snprintf(tool_log, sizeof tool_log, "%s/inspect-%s.log", work, e->d_name);
        if (stat(obj, &st) != 0 || !S_ISREG(st.st_mode)) {
            snprintf(why, size, "parts/%s/%s: the build made no object file from it", folder, e->d_name);
            ok = false;
            break;
        }
        /* The tools read hostile files: they run contained, like the code. */
        char *nm[] = {"nm", "-u", "--format=just-symbols", obj, NULL};
        char *readelf[] = {"readelf", "-S", "-W", obj, NULL};
        char *objdump[] = {"objdump", "-d", obj, NULL};
        struct { char **argv; line_check check; } steps[] = {{nm, bad_symbol}, {readelf, bad_section},
                                                             {objdump, bad_instruction}};
        for (size_t k = 0; ok && k < sizeof steps / sizeof steps[0]; k++) {
            if (!run_to(steps[k].argv, NULL, tool_log, untrusted) ||
                scan(tool_log, steps[k].check, symbols, what, sizeof what)) {
                snprintf(why, size, "parts/%s/%s: %s", folder, e->d_name, what[0] ? what : "could not be inspected "
                         "(not an object file: was it built with link-time optimisation?)");
                ok = false;
            }
        }
    }
    if (d) closedir(d);
    free(symbols);
    return ok;
}
