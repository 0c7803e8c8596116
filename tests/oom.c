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
 *   LOFT_OOM_ABOVE=N    also fail every allocation of more than N bytes
 *                       (a record too large for memory, made small)
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
static size_t above;            /* LOFT_OOM_ABOVE, 0 for none */

/* The decimal number s, 0 for none (getenv's strings: no allocation). */
static unsigned long long
env_number(const char *s)
{
	unsigned long long v = 0;

	for (; s != NULL && *s >= '0' && *s <= '9'; s++)
		v = v * 10 + (unsigned long long)(*s - '0');
	return v;
}

/* Read the settings, once: only for the program LOFT_OOM_PROG names. */
static void
settings(void)
{
	const char *prog = getenv("LOFT_OOM_PROG");
	char exe[4096];
	ssize_t n;

	fail_at = (long)env_number(getenv("LOFT_OOM_FAIL"));
	above = (size_t)env_number(getenv("LOFT_OOM_ABOVE"));
	if (prog != NULL) {
		const char *base;

		/* readlink is a system call: it does not allocate */
		n = readlink("/proc/self/exe", exe, sizeof exe - 1);
		exe[n > 0 ? n : 0] = '\0';
		base = strrchr(exe, '/') ? strrchr(exe, '/') + 1 : exe;
		if (strcmp(base, prog) != 0)
			fail_at = 0, above = 0;
	}
}

/* Count one call of size bytes; nonzero when it is one to fail. */
static int
fail_now(size_t size)
{
	const char *mark;
	int fd;

	if (fail_at < 0)
		settings();
	if (above > 0 && size > above) {
		errno = ENOMEM;
		return 1;
	}
	if (fail_at == 0 || ++calls != fail_at)
		return 0;
	if ((mark = getenv("LOFT_OOM_MARK")) != NULL &&
	    (fd = open(mark, O_WRONLY | O_CREAT | O_TRUNC, 0644)) >= 0)
		close(fd);
	errno = ENOMEM;
	return 1;
}

void *
malloc(size_t n)
{
	return fail_now(n) ? NULL : __libc_malloc(n);
}

void *
calloc(size_t n, size_t sz)
{
	size_t size = sz > 0 && n > (size_t)-1 / sz ? (size_t)-1 : n * sz;

	return fail_now(size) ? NULL : __libc_calloc(n, sz);
}

void *
realloc(void *p, size_t n)
{
	return fail_now(n) ? NULL : __libc_realloc(p, n);
}
