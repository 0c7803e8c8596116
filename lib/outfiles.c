/*
 * outfiles.c: output split into named files, each collected in memory
 * and written whole: to a temporary name beside it, then renamed, so a
 * reader never sees half a file and a failed run leaves the old one.
 * Program layer (loftprog.h): it writes files.
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "loftprog.h"
#include "internal.h"

/* The process's umask (reading it means setting it; put back at once),
 * for a file made by mkstemp to get the mode fopen would give it. */
static mode_t
umask_now(void)
{
	mode_t m = umask(077);

	umask(m);
	return m;
}

/* The file called name, appended if new; NULL when out of memory. */
static struct loft_outfile *
find(struct loft_outfiles *s, const char *name)
{
	struct loft_outfile *f;

	for (size_t i = s->n; i-- > 0;)
		if (strcmp(s->f[i].name, name) == 0)
			return &s->f[i];
	if (loft__grow((void **)&s->f, &s->cap, s->n + 1, sizeof *s->f) != 0)
		return NULL;
	f = &s->f[s->n];
	memset(f, 0, sizeof *f);
	if ((f->name = malloc(strlen(name) + 1)) == NULL)
		return NULL;
	strcpy(f->name, name);
	s->n++;
	return f;
}

int
loft_outfiles_add(struct loft_outfiles *s, const char *name, const char *text,
    size_t len, struct loft_error *err)
{
	struct loft_outfile *f = find(s, name);

	if (f == NULL || loft__grow((void **)&f->buf, &f->cap, f->len + len,
	    1) != 0)
		return loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
	memcpy(f->buf + f->len, text, len);
	f->len += len;
	return 0;
}

int
loft_outfile_write(const struct loft_outfile *f, struct loft_error *err)
{
	size_t n = strlen(f->name);
	char *tmp = malloc(n + 8);
	FILE *fp = NULL;
	int fd, e;

	if (tmp == NULL)
		return loft_fail(err, LOFT_ENOMEM, -1, "%s: out of memory",
		    f->name);
	memcpy(tmp, f->name, n);
	memcpy(tmp + n, ".XXXXXX", 8);
	errno = 0;
	if ((fd = mkstemp(tmp)) < 0) {
		e = errno;
		free(tmp);
		return loft_fail(err, LOFT_EIO, -1, "%s: cannot create: %s",
		    f->name, strerror(e));
	}
	if ((fp = fdopen(fd, "w")) == NULL ||
	    (f->len > 0 && fwrite(f->buf, 1, f->len, fp) != f->len) ||
	    fflush(fp) != 0 || ferror(fp) || fchmod(fd, 0666 & ~umask_now())
	    != 0) {
		e = errno ? errno : EIO;
		fp ? fclose(fp) : close(fd);
		remove(tmp);
		free(tmp);
		return loft_fail(err, LOFT_EIO, -1, "%s: cannot write: %s",
		    f->name, strerror(e));
	}
	if (fclose(fp) != 0 || rename(tmp, f->name) != 0) {
		e = errno ? errno : EIO;
		remove(tmp);
		free(tmp);
		return loft_fail(err, LOFT_EIO, -1, "%s: cannot write: %s",
		    f->name, strerror(e));
	}
	free(tmp);
	return 0;
}

void
loft_outfiles_free(struct loft_outfiles *s)
{
	for (size_t i = 0; i < s->n; i++) {
		free(s->f[i].name);
		free(s->f[i].buf);
	}
	free(s->f);
	memset(s, 0, sizeof *s);
}
