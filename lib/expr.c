/*
 * expr.c: arithmetic expressions in one or two variables, compiled to a
 * small stack program and evaluated in forward-mode automatic
 * differentiation: every value carries its first and second partial
 * derivatives, so bezapprox gets exact tangents and normals, not finite
 * differences.
 *
 * Grammar (the man page bezapprox.1 says the same in words):
 *
 *	sum     = product { ("+" | "-") product }
 *	product = unary { ("*" | "/") unary }
 *	unary   = ("-" | "+") unary | power
 *	power   = atom [ "^" unary ]            (right-associative)
 *	atom    = number | constant | variable | "(" sum ")"
 *	        | function "(" sum ")" | "pow" "(" sum "," sum ")"
 */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "internal.h"

enum op { OP_NUM, OP_VAR, OP_NEG, OP_ADD, OP_SUB, OP_MUL, OP_DIV, OP_POW,
    OP_FUNC };

enum func { F_SIN, F_COS, F_TAN, F_ASIN, F_ACOS, F_ATAN, F_EXP, F_LOG,
    F_SQRT, F_SINH, F_COSH, F_TANH, F_ABS };

static const char *const func_names[] = { "sin", "cos", "tan", "asin",
    "acos", "atan", "exp", "log", "sqrt", "sinh", "cosh", "tanh", "abs" };

struct insn {
	enum op op;
	int arg;                /* variable index or function */
	double num;
};

struct loft_expr {
	struct insn *code;
	int ncode, cap;
	int depth, maxdepth;    /* stack depth while compiling; its peak */
	struct loft_jet *stack;
};

/* The parser's state: the text, where it is, and the variables' names. */
struct parser {
	const char *src, *s;
	const char *vars;
	struct loft_expr *e;
	struct loft_error *err;
	int *col;
	int failed;
	int nest;               /* unary() calls now open */
};

/*
 * How deep an expression may nest: every nesting (a sign, a parenthesis,
 * a function's argument, an exponent) passes through unary(), one C
 * stack frame chain each.  No formula a person writes comes near 200;
 * 130,000 unary minuses ran the stack out.
 */
#define EXPR_MAXNEST 200

static void sum(struct parser *ps);

/* Fail at the place at; the first failure wins. */
static void
fail_at(struct parser *ps, const char *at, const char *fmt, ...)
{
	va_list ap;

	if (ps->failed)
		return;
	ps->failed = 1;
	*ps->col = (int)(at - ps->src) + 1;
	ps->err->row = -1;
	va_start(ap, fmt);
	vsnprintf(ps->err->msg, sizeof ps->err->msg, fmt, ap);
	va_end(ap);
}

static void
emit(struct parser *ps, enum op op, int arg, double num)
{
	struct loft_expr *e = ps->e;
	static const int effect[] = { 1, 1, 0, -1, -1, -1, -1, -1, 0 };

	if (ps->failed)
		return;
	if (e->ncode == e->cap) {
		int cap = e->cap ? 2 * e->cap : 16;
		struct insn *c = realloc(e->code, cap * sizeof *c);

		if (c == NULL) {
			fail_at(ps, ps->s, "out of memory");
			return;
		}
		e->code = c;
		e->cap = cap;
	}
	e->code[e->ncode++] = (struct insn){ op, arg, num };
	e->depth += effect[op];
	if (e->depth > e->maxdepth)
		e->maxdepth = e->depth;
}

static void
skip_space(struct parser *ps)
{
	while (*ps->s == ' ' || *ps->s == '\t')
		ps->s++;
}

/* Accept the character c (after blanks), or leave the place alone. */
static int
accept(struct parser *ps, char c)
{
	skip_space(ps);
	if (*ps->s != c)
		return 0;
	ps->s++;
	return 1;
}

/* Fail where the parser wanted something else, saying what it found. */
static void
expect_failure(struct parser *ps, const char *want)
{
	if (*ps->s == '\0')
		fail_at(ps, ps->s, "%s, found the end", want);
	else
		fail_at(ps, ps->s, "%s, found '%c'", want, *ps->s);
}

static void
number(struct parser *ps)
{
	const char *a = ps->s, *s = ps->s;
	double x;

	while (isdigit((unsigned char)*s))
		s++;
	if (*s == '.')
		for (s++; isdigit((unsigned char)*s); s++)
			;
	if ((*s == 'e' || *s == 'E') && (isdigit((unsigned char)s[1]) ||
	    ((s[1] == '+' || s[1] == '-') && isdigit((unsigned char)s[2]))))
		for (s += 2; isdigit((unsigned char)*s); s++)
			;
	if (loft_parse_num(a, (size_t)(s - a), &x, NULL) != 0) {
		fail_at(ps, a, "number %.*s out of range", (int)(s - a), a);
		return;
	}
	ps->s = s;
	emit(ps, OP_NUM, 0, x);
}

/* A function's argument list: "(" sum ")" or, for pow, "(" sum "," sum ")". */
static void
call(struct parser *ps, const char *name, int nargs)
{
	if (!accept(ps, '(')) {
		expect_failure(ps, nargs == 2 ? "expected '(' after pow" :
		    "expected '(' after a function's name");
		return;
	}
	sum(ps);
	if (nargs == 2 && !accept(ps, ','))
		expect_failure(ps, "expected ',' between pow's two arguments");
	if (nargs == 2)
		sum(ps);
	if (!accept(ps, ')'))
		expect_failure(ps, strcmp(name, "pow") == 0 && nargs == 1 ?
		    "expected ','" : "expected ')'");
}

static void
name(struct parser *ps)
{
	const char *a = ps->s;
	char word[32];
	size_t len;

	while (isalnum((unsigned char)*ps->s))
		ps->s++;
	len = (size_t)(ps->s - a);
	if (len >= sizeof word) {
		fail_at(ps, a, "name too long");
		return;
	}
	memcpy(word, a, len);
	word[len] = '\0';
	if (len == 1 && strchr(ps->vars, word[0]) != NULL) {
		emit(ps, OP_VAR, (int)(strchr(ps->vars, word[0]) - ps->vars), 0);
		return;
	}
	if (strcmp(word, "pi") == 0 || strcmp(word, "e") == 0) {
		emit(ps, OP_NUM, 0, word[0] == 'p' ? M_PI : M_E);
		return;
	}
	if (strcmp(word, "pow") == 0) {
		call(ps, word, 2);
		emit(ps, OP_POW, 0, 0);
		return;
	}
	for (size_t f = 0; f < sizeof func_names / sizeof func_names[0]; f++)
		if (strcmp(word, func_names[f]) == 0) {
			call(ps, word, 1);
			emit(ps, OP_FUNC, (int)f, 0);
			return;
		}
	skip_space(ps);
	if (*ps->s == '(')
		fail_at(ps, a, "unknown function '%s'", word);
	else if (ps->vars[1] == '\0')
		fail_at(ps, a, "unknown name '%s' (the variable here is %c)",
		    word, ps->vars[0]);
	else
		fail_at(ps, a, "unknown name '%s' (the variables here are %c "
		    "and %c)", word, ps->vars[0], ps->vars[1]);
}

static void
atom(struct parser *ps)
{
	skip_space(ps);
	if (isdigit((unsigned char)*ps->s) || (*ps->s == '.' &&
	    isdigit((unsigned char)ps->s[1])))
		number(ps);
	else if (isalpha((unsigned char)*ps->s))
		name(ps);
	else if (accept(ps, '(')) {
		sum(ps);
		if (!accept(ps, ')'))
			expect_failure(ps, "expected ')'");
	} else
		expect_failure(ps, "expected a number, a name or '('");
}

static void unary(struct parser *ps);

static void
power(struct parser *ps)
{
	atom(ps);
	if (accept(ps, '^')) {
		unary(ps);
		emit(ps, OP_POW, 0, 0);
	}
}

static void
unary(struct parser *ps)
{
	if (ps->nest >= EXPR_MAXNEST) {
		skip_space(ps);
		fail_at(ps, ps->s, "nested more than %d deep", EXPR_MAXNEST);
		return;
	}
	ps->nest++;
	if (accept(ps, '-')) {
		unary(ps);
		emit(ps, OP_NEG, 0, 0);
	} else if (accept(ps, '+'))
		unary(ps);
	else
		power(ps);
	ps->nest--;
}

static void
product(struct parser *ps)
{
	unary(ps);
	while (!ps->failed) {
		if (accept(ps, '*')) {
			unary(ps);
			emit(ps, OP_MUL, 0, 0);
		} else if (accept(ps, '/')) {
			unary(ps);
			emit(ps, OP_DIV, 0, 0);
		} else
			return;
	}
}

static void
sum(struct parser *ps)
{
	product(ps);
	while (!ps->failed) {
		if (accept(ps, '+')) {
			product(ps);
			emit(ps, OP_ADD, 0, 0);
		} else if (accept(ps, '-')) {
			product(ps);
			emit(ps, OP_SUB, 0, 0);
		} else
			return;
	}
}

void
loft_expr_free(struct loft_expr *e)
{
	if (e == NULL)
		return;
	free(e->code);
	free(e->stack);
	free(e);
}

struct loft_expr *
loft_expr_parse(const char *src, const char *vars, int *col,
    struct loft_error *err)
{
	struct loft_expr *e;
	struct parser ps = { src, src, vars, NULL, err, col, 0, 0 };

	*col = 0;
	if (strlen(vars) < 1 || strlen(vars) > 2) {
		loft_fail(err, LOFT_EINPUT, -1, "%zu variables: want 1 or 2",
		    strlen(vars));
		return NULL;
	}
	ps.e = e = calloc(1, sizeof *e);
	if (e == NULL) {
		loft_fail(err, LOFT_ENOMEM, -1, "out of memory");
		return NULL;
	}
	sum(&ps);
	skip_space(&ps);
	if (!ps.failed && *ps.s != '\0')
		expect_failure(&ps, "expected an operator");
	if (!ps.failed) {
		e->stack = malloc((size_t)e->maxdepth * sizeof *e->stack);
		if (e->stack == NULL)
			fail_at(&ps, ps.s, "out of memory");
	}
	if (ps.failed) {
		loft_expr_free(e);
		return NULL;
	}
	return e;
}

/*
 * The chain rule for r = f(a), given f(a), f'(a) and f''(a):
 * r_k = f' a_k and r_kl = f' a_kl + f'' a_k a_l.
 */
static void
chain(struct loft_jet *r, const struct loft_jet *a, double f0, double f1,
    double f2)
{
	struct loft_jet x = *a;

	r->v = f0;
	r->d[0] = f1 * x.d[0];
	r->d[1] = f1 * x.d[1];
	r->h[0] = f1 * x.h[0] + f2 * x.d[0] * x.d[0];
	r->h[1] = f1 * x.h[1] + f2 * x.d[0] * x.d[1];
	r->h[2] = f1 * x.h[2] + f2 * x.d[1] * x.d[1];
}

/* The product rule: (ab)_kl = a_kl b + a_k b_l + a_l b_k + a b_kl. */
static void
mul(struct loft_jet *r, const struct loft_jet *a, const struct loft_jet *b)
{
	struct loft_jet x = *a, y = *b;

	r->v = x.v * y.v;
	r->d[0] = x.d[0] * y.v + x.v * y.d[0];
	r->d[1] = x.d[1] * y.v + x.v * y.d[1];
	r->h[0] = x.h[0] * y.v + 2 * x.d[0] * y.d[0] + x.v * y.h[0];
	r->h[1] = x.h[1] * y.v + x.d[0] * y.d[1] + x.d[1] * y.d[0] +
	    x.v * y.h[1];
	r->h[2] = x.h[2] * y.v + 2 * x.d[1] * y.d[1] + x.v * y.h[2];
}

/* a += b */
static void
add(struct loft_jet *a, const struct loft_jet *b)
{
	a->v += b->v;
	for (int k = 0; k < 2; k++)
		a->d[k] += b->d[k];
	for (int k = 0; k < 3; k++)
		a->h[k] += b->h[k];
}

/* a = 1 / a */
static void
recip(struct loft_jet *a)
{
	double x = a->v;

	chain(a, a, 1 / x, -1 / (x * x), 2 / (x * x * x));
}

static int
is_constant(const struct loft_jet *a)
{
	return a->d[0] == 0 && a->d[1] == 0 && a->h[0] == 0 &&
	    a->h[1] == 0 && a->h[2] == 0;
}

/*
 * a^b.  A constant exponent uses the power rule, so that negative bases
 * and integer powers work (cos(pi*v)^2); terms whose coefficient is
 * exactly zero are left out, so t^2 and t^1 have finite derivatives at
 * t = 0.  A varying exponent is exp(b log a), defined for a > 0 only.
 */
static void
power_jet(struct loft_jet *r, const struct loft_jet *a, const struct loft_jet *b)
{
	if (is_constant(b)) {
		double c = b->v, x = a->v;
		double f1 = c == 0 ? 0 : c * pow(x, c - 1);
		double f2 = c == 0 || c == 1 ? 0 : c * (c - 1) * pow(x, c - 2);

		chain(r, a, pow(x, c), f1, f2);
		return;
	}
	struct loft_jet l;

	chain(&l, a, log(a->v), 1 / a->v, -1 / (a->v * a->v));
	mul(&l, &l, b);
	chain(r, &l, exp(l.v), exp(l.v), exp(l.v));
}

static void
func(struct loft_jet *r, int f, const struct loft_jet *a)
{
	double x = a->v, s, q;

	switch (f) {
	case F_SIN: chain(r, a, sin(x), cos(x), -sin(x)); break;
	case F_COS: chain(r, a, cos(x), -sin(x), -cos(x)); break;
	case F_TAN:
		s = tan(x);
		chain(r, a, s, 1 + s * s, 2 * s * (1 + s * s));
		break;
	case F_ASIN:
	case F_ACOS:
		q = 1 - x * x;
		s = f == F_ASIN ? 1 : -1;
		chain(r, a, f == F_ASIN ? asin(x) : acos(x), s / sqrt(q),
		    s * x / (q * sqrt(q)));
		break;
	case F_ATAN:
		q = 1 + x * x;
		chain(r, a, atan(x), 1 / q, -2 * x / (q * q));
		break;
	case F_EXP: s = exp(x); chain(r, a, s, s, s); break;
	case F_LOG: chain(r, a, log(x), 1 / x, -1 / (x * x)); break;
	case F_SQRT:
		s = sqrt(x);
		chain(r, a, s, 0.5 / s, -0.25 / (s * x));
		break;
	case F_SINH: chain(r, a, sinh(x), cosh(x), sinh(x)); break;
	case F_COSH: chain(r, a, cosh(x), sinh(x), cosh(x)); break;
	case F_TANH:
		s = tanh(x);
		chain(r, a, s, 1 - s * s, -2 * s * (1 - s * s));
		break;
	default:        /* F_ABS: the slope's sign; 0 at the kink */
		chain(r, a, fabs(x), (x > 0) - (x < 0), 0);
		break;
	}
}

void
loft_expr_eval(struct loft_expr *e, const double *x, struct loft_jet *out)
{
	struct loft_jet *st = e->stack, neg;
	int sp = 0;

	for (int i = 0; i < e->ncode; i++) {
		const struct insn *c = &e->code[i];

		switch (c->op) {
		case OP_NUM:
			st[sp++] = (struct loft_jet){ c->num, { 0, 0 },
			    { 0, 0, 0 } };
			break;
		case OP_VAR:
			st[sp] = (struct loft_jet){ x[c->arg], { 0, 0 },
			    { 0, 0, 0 } };
			st[sp++].d[c->arg] = 1;
			break;
		case OP_NEG:
			chain(&st[sp - 1], &st[sp - 1], -st[sp - 1].v, -1, 0);
			break;
		case OP_ADD:
		case OP_SUB:
			neg = st[sp - 1];
			if (c->op == OP_SUB)
				chain(&neg, &neg, -neg.v, -1, 0);
			add(&st[sp - 2], &neg);
			sp--;
			break;
		case OP_MUL:
			mul(&st[sp - 2], &st[sp - 2], &st[sp - 1]);
			sp--;
			break;
		case OP_DIV:
			recip(&st[sp - 1]);
			mul(&st[sp - 2], &st[sp - 2], &st[sp - 1]);
			sp--;
			break;
		case OP_POW:
			power_jet(&st[sp - 2], &st[sp - 2], &st[sp - 1]);
			sp--;
			break;
		case OP_FUNC:
			func(&st[sp - 1], c->arg, &st[sp - 1]);
			break;
		}
	}
	*out = st[0];
}
