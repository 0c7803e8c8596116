/*
 * embed: write the C source of loftplot -i's page (issue 27) to standard
 * output: the page template lib/wasm/page.html cut at its line
 * <!--LOFT-DATA--> into loft_page_head and loft_page_tail, and the
 * WebAssembly module, when one is named, in base64 as loft_page_wasm
 * (an empty list when none is).  Each is a NULL-ended list of string
 * literals of at most PIECE characters, within what C99 lets a literal
 * be (4095).  Run by the Makefile at build time; never installed.
 *
 *	embed page.html [module.wasm] > page.c
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PIECE 3000
#define MARK "<!--LOFT-DATA-->"

/* The whole of file name, its length in *n; exits 1 on failure. */
static unsigned char *
slurp(const char *name, size_t *n)
{
	FILE *fp = fopen(name, "rb");
	unsigned char *b = NULL;
	size_t cap = 0;

	*n = 0;
	if (fp == NULL) {
		perror(name);
		exit(1);
	}
	for (;;) {
		if (*n == cap) {
			unsigned char *g;

			cap = cap ? 2 * cap : 65536;
			if ((g = realloc(b, cap + 1)) == NULL) {
				perror("embed");
				exit(1);
			}
			b = g;
		}
		size_t k = fread(b + *n, 1, cap - *n, fp);
		if (k == 0)
			break;
		*n += k;
	}
	if (ferror(fp)) {
		perror(name);
		exit(1);
	}
	fclose(fp);
	b[*n] = '\0';
	return b;
}

/* The list name of the n bytes of s as C string literals. */
static void
list(const char *name, const unsigned char *s, size_t n)
{
	printf("const char *const %s[] = {\n", name);
	for (size_t i = 0; i < n; i += PIECE) {
		fputs("\"", stdout);
		for (size_t j = i; j < n && j < i + PIECE; j++) {
			int c = s[j];

			if (c == '\\' || c == '"')
				printf("\\%c", c);
			else if (c == '\n')
				fputs("\\n", stdout);
			else if (c < 32 || c > 126)
				printf("\\%03o", c);
			else
				putchar(c);
		}
		fputs("\",\n", stdout);
	}
	puts("NULL };");
}

/* The base64 of the n bytes of b (RFC 4648, with padding). */
static unsigned char *
base64(const unsigned char *b, size_t n, size_t *len)
{
	static const char a[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
	    "0123456789+/";
	unsigned char *s = malloc(4 * (n / 3 + 1) + 1), *p = s;

	if (s == NULL) {
		perror("embed");
		exit(1);
	}
	for (size_t i = 0; i < n; i += 3) {
		unsigned long v = (unsigned long)b[i] << 16 |
		    (i + 1 < n ? (unsigned long)b[i + 1] << 8 : 0) |
		    (i + 2 < n ? b[i + 2] : 0);

		*p++ = a[v >> 18 & 63];
		*p++ = a[v >> 12 & 63];
		*p++ = i + 1 < n ? a[v >> 6 & 63] : '=';
		*p++ = i + 2 < n ? a[v & 63] : '=';
	}
	*len = (size_t)(p - s);
	return s;
}

int
main(int argc, char *argv[])
{
	unsigned char *page, *mod = NULL, *b64 = NULL, *mark;
	size_t n, m = 0, k = 0;

	if (argc < 2 || argc > 3) {
		fputs("usage: embed page.html [module.wasm]\n", stderr);
		return 2;
	}
	page = slurp(argv[1], &n);
	if ((mark = (unsigned char *)strstr((char *)page, MARK)) == NULL) {
		fprintf(stderr, "embed: %s: no line %s\n", argv[1], MARK);
		return 1;
	}
	if (argc == 3) {
		mod = slurp(argv[2], &m);
		b64 = base64(mod, m, &k);
	}
	puts("/* made by lib/wasm/embed.c from lib/wasm/page.html and the"
	    " module: not edited */\n#include <stddef.h>\n"
	    "#include \"wasm/page.h\"");
	list("loft_page_head", page, (size_t)(mark - page));
	mark += strlen(MARK);
	list("loft_page_tail", mark, n - (size_t)(mark - page));
	list("loft_page_wasm", b64, k);
	printf("const size_t loft_page_wasm_bytes = %zu;\n", m);
	free(page);
	free(mod);
	free(b64);
	return ferror(stdout) ? 1 : 0;
}
