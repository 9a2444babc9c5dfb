/* Grader machinery: not part of any assignment.
 * The compiler's messages a student sees (grade_diag.h): only those about the student's own files.
 * GCC prints a diagnostic as a header line "path:line:col: error: message", then excerpt lines of
 * that file (" 12 | code", "    |  ^~~"). A header about any other file (an #include of a hidden
 * scene, a framework header, /etc/passwd) would quote that file's line, so the grader keeps a
 * header, and the excerpt under it, only when its path is the part's own folder; every other line
 * (make's, "In file included from", another file's header and excerpt) is dropped. The linker's
 * "undefined reference" lines are kept when they name the part's own objects. What is kept is made
 * valid UTF-8 without control characters (each bad byte a '?'), and bounded by lines and bytes. */
#include "grade_diag.h"
#include "grade_limits.h"
#include "../framework/file.h"
#include <fcntl.h>
#include <unistd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A header line about the part's own files: "parts/<folder>/<file>:" with no ".." or second slash. */
static bool own_header(const char *line, const char *own)
{
    size_t n = strlen(own);
    if (strncmp(line, own, n)) return false;
    const char *colon = strchr(line + n, ':');
    return colon && colon > line + n && !memchr(line + n, '/', (size_t)(colon - line - n)) && !strstr(line, "..");
}

/* An excerpt line: starts with a space (GCC indents " 12 | code" and "    |   ^") or a digit column. */
static bool excerpt_line(const char *line)
{
    return line[0] == ' ' || line[0] == '\t';
}

/* The linker's message about the part's own object ("/usr/bin/ld: build/release/parts/<folder>/x.o: ..."). */
static bool own_link_line(const char *line, const char *folder)
{
    char object[300];
    snprintf(object, sizeof object, "build/release/parts/%s/", folder);  /* folder: the course's, under 64 */
    return (!strncmp(line, "/usr/bin/ld: ", 13) || !strncmp(line, "ld: ", 4)) && strstr(line, object) &&
           !strstr(line, "..");
}

/* The length of the valid UTF-8 sequence at p (1 to 4), or 0 (RFC 3629: no overlong forms, no
 * surrogates, nothing above U+10FFFF). */
static int utf8_length(const unsigned char *p)
{
    if (p[0] < 0x80) return 1;
    int n = p[0] >= 0xC2 && p[0] <= 0xDF ? 2 : p[0] >= 0xE0 && p[0] <= 0xEF ? 3 : p[0] >= 0xF0 && p[0] <= 0xF4 ? 4 : 0;
    unsigned char lo = p[0] == 0xE0 ? 0xA0 : p[0] == 0xF0 ? 0x90 : 0x80;
    unsigned char hi = p[0] == 0xED ? 0x9F : p[0] == 0xF4 ? 0x8F : 0xBF;
    if (n == 0 || p[1] < lo || p[1] > hi) return 0;
    for (int i = 2; i < n; i++)
        if (p[i] < 0x80 || p[i] > 0xBF) return 0;
    return n;
}

/* In place: every byte that is not part of valid UTF-8, and every control character but the tab
 * and the newline (a terminal escape in a message), becomes '?'. */
static void make_printable(char *text)
{
    unsigned char *p = (unsigned char *)text;
    while (*p) {
        int n = utf8_length(p);
        if (n == 0 || (n == 1 && *p < 0x20 && *p != '\t' && *p != '\n') || *p == 0x7F) *p = '?', n = 1;
        p += n;
    }
}

void grade_diagnostics(const char *log, const char *folder, int max_lines, char *out, size_t size)
{
    out[0] = '\0';
    char *text = NULL, own[300];
    size_t len = 0, used = 0;
    pl_diag diag = pl_diag_default();
    if (file_read_all(log, "build log", GRADE_TOOL_LOG_MAX, &text, &len, &diag) != PL_OK) return;
    snprintf(own, sizeof own, "parts/%s/", folder);
    bool keeping = false;  /* inside a kept header's excerpt */
    int kept = 0;
    for (char *save = NULL, *line = strtok_r(text, "\n", &save); line && kept < max_lines; line = strtok_r(NULL, "\n", &save)) {
        if (excerpt_line(line)) {
            if (!keeping) continue;
        }
        else keeping = own_header(line, own);
        if (!keeping && !own_link_line(line, folder)) continue;
        size_t n = strlen(line);
        if (used + n + 2 > size) break;
        memcpy(out + used, line, n);
        used += n;
        out[used++] = '\n';
        out[used] = '\0';
        kept++;
    }
    if (used > 0) out[used - 1] = '\0';
    make_printable(out);
    free(text);
}

/* ---- the end of a log ----------------------------------------------------------------------- */

/* make's quiet progress lines ("  CC     framework/rng.c"): no help in finding the error. */
static bool progress_line(const char *line)
{
    return !strncmp(line, "  CC ", 5) || !strncmp(line, "  LD ", 5);
}

void grade_log_tail(const char *path, int lines, char *out, size_t size)
{
    out[0] = '\0';
    int fd = path ? open(path, O_RDONLY | O_NOFOLLOW | O_CLOEXEC) : -1;
    char window[65536];  /* the end of the log, where the error is */
    off_t end = fd >= 0 ? lseek(fd, 0, SEEK_END) : 0, start = end > (off_t)sizeof window - 1 ? end - (off_t)sizeof window + 1 : 0;
    ssize_t n = fd >= 0 && size > 1 ? pread(fd, window, (size_t)(end - start), start) : -1;
    if (fd >= 0) close(fd);
    if (n <= 0) return;
    window[n] = '\0';
    /* Walk back over whole lines (less a first line the window cut) until `lines` are kept or the
     * next would not fit; then copy them out in order. */
    char *first = start > 0 && strchr(window, '\n') ? strchr(window, '\n') + 1 : window;
    char *kept[256];
    int count = 0;
    size_t used = 0;
    for (char *p = window + n; p > first && count < lines && count < 256;) {
        while (p > first && p[-1] == '\n') *--p = '\0';
        char *line = p;
        while (line > first && line[-1] != '\n') line--;
        if (line == p) break;
        if (!progress_line(line)) {
            if (used + strlen(line) + 1 >= size) break;
            used += strlen(line) + 1;
            kept[count++] = line;
        }
        p = line;
    }
    for (int i = count - 1; i >= 0; i--) {
        strcat(out, kept[i]);
        if (i > 0) strcat(out, "\n");
    }
}
