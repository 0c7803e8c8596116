/*
 * oom.c: a preloaded shim that makes the k-th allocation of a program
 * fail, for tests/oom.sh (issue 12, after SQLite's out-of-memory loops).
 *
 *   LOFT_OOM_FAIL=k     malloc, calloc and realloc are counted from 1 in
 *                       the order the process calls them; call k returns
 *                       NULL with errno ENOMEM, every other one succeeds
 *   LOFT_OOM_MARK=FILE  created when call k came, so that the loop knows
 *                       the run reached it (a run of fewer calls ends it)
 *   LOFT_OOM_PROG=NAME  only in a process whose executable is called
 *                       NAME (so a timeout(1) around it runs unharmed)
 *
 * Built as a shared object (make builds bin/test/oom.so) and used as
 * LD_PRELOAD=bin/test/oom.so PROG ...  It calls glibc's own allocator
 * (__libc_malloc and its kin) rather than dlsym(RTLD_NEXT), which itself
 * allocates; so it needs glibc, and tests/oom.sh skips itself elsewhere.
 * It cannot go under AddressSanitizer, which must own malloc: the suite
 * skips itself for a sanitized build (make check-san) too.
 */
#include <errno.h>
#include <fcntl.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void *__libc_malloc(size_t);
void *__libc_calloc(size_t, size_t);
void *__libc_realloc(void *, size_t);

static long calls;              /* allocations so far */
static long fail_at = -1;       /* LOFT_OOM_FAIL, 0 for none; -1 unread */

/* Count one call; nonzero when this is the one to fail. */
static int
fail_now(void)
{
	if (fail_at < 0) {
		/* getenv does not allocate */
		const char *s = getenv("LOFT_OOM_FAIL");

		const char *prog = getenv("LOFT_OOM_PROG");
		char exe[4096];
		ssize_t n;

		fail_at = 0;
		for (; s != NULL && *s >= '0' && *s <= '9'; s++)
			fail_at = fail_at * 10 + (*s - '0');
		/* readlink is a system call: it does not allocate */
		if (prog != NULL) {
			const char *base;

			n = readlink("/proc/self/exe", exe, sizeof exe - 1);
			exe[n > 0 ? n : 0] = '\0';
			base = strrchr(exe, '/') ? strrchr(exe, '/') + 1 : exe;
			if (strcmp(base, prog) != 0)
				fail_at = 0;
		}
	}
	if (fail_at == 0 || ++calls != fail_at)
		return 0;
	{
		const char *mark = getenv("LOFT_OOM_MARK");
		int fd;

		if (mark != NULL && (fd = open(mark, O_WRONLY | O_CREAT |
		    O_TRUNC, 0644)) >= 0)
			close(fd);
	}
	errno = ENOMEM;
	return 1;
}

void *
malloc(size_t n)
{
	return fail_now() ? NULL : __libc_malloc(n);
}

void *
calloc(size_t n, size_t sz)
{
	return fail_now() ? NULL : __libc_calloc(n, sz);
}

void *
realloc(void *p, size_t n)
{
	return fail_now() ? NULL : __libc_realloc(p, n);
}
