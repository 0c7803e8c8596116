/*
 * pageout.c: loftplot -i's page (issue 27): the template and module
 * that lib/wasm/embed.c made into C at build time, with the records
 * given to loftplot between them as JSON.
 */
#include <stdio.h>
#include <string.h>

#include "wasm/page.h"

static void
put_pieces(FILE *out, const char *const *s)
{
	for (; *s != NULL; s++)
		fputs(*s, out);
}

/* The n bytes of s as a JSON string: quotes, backslashes and control
 * characters escaped, and '<', so that no </script> ends the data. */
static void
put_json(FILE *out, const char *s, size_t n)
{
	putc('"', out);
	for (size_t i = 0; i < n; i++) {
		unsigned char c = (unsigned char)s[i];

		if (c == '"' || c == '\\')
			fprintf(out, "\\%c", c);
		else if (c == '\n')
			fputs("\\n", out);
		else if (c < 32 || c == '<' || c == 127)
			fprintf(out, "\\u%04x", c);
		else
			putc(c, out);
	}
	putc('"', out);
}

static void
put_field(FILE *out, const char *key, const struct loft_writer *w)
{
	fprintf(out, ",\n\"%s\": ", key);
	put_json(out, w->buf != NULL ? w->buf : "", w->len);
}

int
loft_page_write(FILE *out, const struct loft_page *pg)
{
	if (loft_page_wasm_bytes == 0)
		return -1;
	put_pieces(out, loft_page_head);
	fputs("<script id=\"loft-data\" type=\"application/json\">\n{\"view\": ",
	    out);
	put_json(out, pg->view, strlen(pg->view));
	fprintf(out, ", \"comb\": %s, \"args\": [", pg->comb ? "true" :
	    "false");
	for (int i = 0; i < pg->nargs; i++) {
		if (i > 0)
			putc(',', out);
		put_json(out, pg->args[i], strlen(pg->args[i]));
	}
	putc(']', out);
	put_field(out, "knots", &pg->knots);
	put_field(out, "curves", &pg->curves);
	put_field(out, "points", &pg->points);
	put_field(out, "design", &pg->design);
	fputs(",\n\"module\": \"", out);
	put_pieces(out, loft_page_wasm);
	fputs("\"}\n</script>", out);
	put_pieces(out, loft_page_tail);
	return fflush(out) != 0 || ferror(out) ? -1 : 0;
}
