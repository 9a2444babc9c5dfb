/* Grader machinery: not part of any assignment.
 * The operating system's part of the sandbox: what confines a process that runs student code from
 * its first instruction, and what makes sure nothing it started outlives its stage. One interface,
 * two implementations: grader/sandbox_linux.c (seccomp through Debian's libseccomp, a subreaper),
 * used wherever the build finds libseccomp, and grader/sandbox_posix.c (no filter: the grader then
 * refuses to grade a submission as root, and says why), everywhere else. */
#ifndef PL_SANDBOX_H
#define PL_SANDBOX_H

#include <stdbool.h>
#include <stddef.h>

/* The descriptor slot the confined exec runs from; the child's RLIMIT_NOFILE is set to it, so no
 * descriptor can ever be made there again (sandbox_linux.c says why that matters). */
#define SANDBOX_EXEC_FD 255

/* Whether a filter can be installed here (tries it in a throwaway child); false with why. */
bool sandbox_filter_supported(char *why, size_t size);
/* The filter's name and version for the staff log ("seccomp (libseccomp 2.5.4)"), or "none". */
void sandbox_filter_name(char *out, size_t size);

/* In a forked child, as its last step: no_new_privs, the filter, and exec of argv (a path, or a
 * name looked up in PATH) as the only exec the process will ever make. may_write_files: the filter
 * lets it create and write files (the legacy XML suite; nothing else). Returns only on failure. */
void sandbox_exec(char *const argv[], bool may_write_files);

/* In a forked child that will not exec (a function of the grader's reading hostile files: the
 * object inspection), as its last privileged step: no_new_privs and the same filter, with no exec
 * at all (the exec slot can never be opened). False when it could not be installed. */
bool sandbox_confine_self(void);

/* PID and mount namespaces (Linux, as root; Docker's default seccomp profile refuses them): whether
 * this machine gives them, tried in a throwaway child. */
bool sandbox_isolation_supported(void);
/* In a forked child, still privileged, before the drop: new PID and mount namespaces and a fresh
 * /proc that shows only them. The calling process stays behind as a relay and never returns: it
 * ends as the confined process ends (same exit status, same signal). The process that returns is
 * the only child of the namespace's init and goes on to drop privileges and exec; when it ends,
 * init ends, and the kernel kills whatever is left in the namespace (a setsid grandchild, a
 * double-forked daemon), none of which could see or signal a process outside it. _exit(126) when
 * a step fails (the probe found them, so this is not expected). */
void sandbox_isolate(void);

/* In the child sandbox_isolate returned to, still privileged: the stage's private view of the file
 * system. Everything becomes read-only; /dev holds only null, zero and urandom (a file that blocks
 * when read, a terminal, a device of the machine's, is out of view); /tmp, /var/tmp and /dev/shm
 * become fresh tmpfs of tmp_bytes each, which vanish with the namespace; `keep` (the sandbox's folder, which may sit under /tmp)
 * stays where it is, read-only; `writable` (NULL: none), a folder under it, is the one place the
 * stage may write. False when a step was refused (the caller ends the child: _exit(126)). */
bool sandbox_private_view(const char *keep, const char *writable, long tmp_bytes);

/* Without namespaces: removes what the sandbox's user (uid) left at the top of /tmp, /var/tmp and
 * /dev/shm, so that nothing a stage wrote there survives it (the stage's only way to write there is
 * the compiler's temporary files; the filter forbids creating files to student code). */
void sandbox_clean_shared_tmp(unsigned uid);

/* The grader adopts every orphan of its children (Linux: a subreaper), so none can escape. */
void sandbox_adopt_orphans(void);
/* Kills and reaps every descendant the grader adopted, e.g. a grandchild that called setsid. */
void sandbox_kill_orphans(void);

#endif
