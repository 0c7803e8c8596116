/*
 * unit.c: unit tests of libloft.  Reference values come from hand
 * derivations (given in the comments) or from independent formulas, never
 * from the library's own output.
 */
#include <float.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "loftprog.h"
#include "check.h"

/* ------------------------------------------------------------------ */
/* numbers */

static void
test_parse_num(void)
{
	static const struct { const char *s; double want; } good[] = {
		{ "1", 1 }, { "-2.5e3", -2500 }, { ".5", 0.5 }, { "5.", 5 },
		{ "+7", 7 }, { "1E2", 100 }, { "0.1", 0.1 },
		{ "1e-320", 1e-320 },           /* subnormal: accepted */
		{ "1e-400", 0 },                /* underflow to zero: accepted */
	};
	static const char *const bad[] = { "", "nan", "NaN", "inf",
		"-infinity", "0x10", "1e400", "-1e309", "1.2.3", "1e", "+",
		"-", ".", "e5", "1,2", "1 2", "12a", "--1", "1e+", "١" };
	struct loft_error err;
	double x;

	for (size_t i = 0; i < sizeof good / sizeof good[0]; i++) {
		int rc = loft_parse_num(good[i].s, strlen(good[i].s), &x, &err);
		CHECK(rc == 0 && x == good[i].want, "parse '%s'", good[i].s);
	}
	CHECK(loft_parse_num("-0", 2, &x, &err) == 0 && x == 0 && signbit(x),
	    "-0 reads as minus zero");
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
		CHECK(loft_parse_num(bad[i], strlen(bad[i]), &x, &err) ==
		    LOFT_EINPUT, "'%s' refused", bad[i]);
}

static void
test_parse_list_int(void)
{
	struct loft_error err;
	double v[3];
	long w;
	int n;

	CHECK(loft_parse_list("1,-0.5,2e1", v, 3, &n, &err) == 0 && n == 3 &&
	    v[0] == 1 && v[1] == -0.5 && v[2] == 20, "list of three");
	CHECK(loft_parse_list("1,2,3,4", v, 3, &n, &err) != 0, "four of 3");
	CHECK(loft_parse_list("1,,2", v, 3, &n, &err) != 0, "empty item");
	CHECK(loft_parse_list("1,", v, 3, &n, &err) != 0, "trailing comma");
	CHECK(loft_parse_int("17", 1, 17, &w, &err) == 0 && w == 17, "17");
	CHECK(loft_parse_int("18", 1, 17, &w, &err) != 0, "18 > 17");
	CHECK(loft_parse_int("0", 1, 17, &w, &err) != 0, "0 < 1");
	CHECK(loft_parse_int("-1", 0, 17, &w, &err) != 0, "sign refused");
	CHECK(loft_parse_int("99999999999999999999999", 1, 17, &w, &err) != 0,
	    "overflow refused");
	CHECK(loft_parse_int("3x", 1, 17, &w, &err) != 0, "garbage refused");
}

/* Every formatted number reads back to the same double, no longer than
 * %.17g would be. */
static void
test_format_roundtrip(void)
{
	char buf[LOFT_NUMBUF], ref[64];
	unsigned long long s = 88172645463325252ULL;
	int bad = 0, longer = 0;

	for (int i = 0; i < 200000; i++) {
		double x;
		unsigned long long bits;

		s ^= s << 13, s ^= s >> 7, s ^= s << 17;       /* xorshift */
		bits = s;
		memcpy(&x, &bits, sizeof x);
		if (!isfinite(x))
			continue;
		loft_format_num(buf, x, 0);
		if (strtod(buf, NULL) != x)
			bad++;
		if (strlen(buf) > (size_t)snprintf(ref, sizeof ref, "%.17g", x))
			longer++;
	}
	CHECK(bad == 0, "%d random doubles did not round-trip", bad);
	CHECK(longer == 0, "%d outputs longer than %%.17g", longer);
	loft_format_num(buf, 0.1, 0);
	CHECK(strcmp(buf, "0.1") == 0, "0.1 prints as %s", buf);
	loft_format_num(buf, -0.0, 0);
	CHECK(strcmp(buf, "0") == 0, "minus zero prints as %s", buf);
	loft_format_num(buf, DBL_MIN / 4, 0);
	CHECK(strtod(buf, NULL) == DBL_MIN / 4, "subnormal %s", buf);
	loft_format_num(buf, 1.0 / 3, 6);
	CHECK(strcmp(buf, "0.333333") == 0, "6 digits: %s", buf);
}

/* ------------------------------------------------------------------ */
/* the reader */

struct stream {
	FILE *fp;
	struct loft_reader *rd;
	struct loft_record rec;
	struct loft_error err;
};

static void
open_text(struct stream *s, const char *text, size_t len)
{
	memset(s, 0, sizeof *s);
	s->fp = fmemopen((void *)text, len, "r");
	s->rd = loft_reader_new(s->fp, "t");
}

static int
next(struct stream *s)
{
	return loft_read(s->rd, &s->rec, &s->err);
}

static void
close_text(struct stream *s)
{
	loft_record_free(&s->rec);
	loft_reader_free(s->rd);
	fclose(s->fp);
}

static void
test_reader_good(void)
{
	static const char text[] =
	    "# a comment line\n"
	    "\n"
	    "1 2   # trailing comment\n"
	    "3 4\r\n"                       /* CRLF */
	    "# comment inside a record\n"
	    "5\t6\n"
	    "   \n"
	    "cubic closed=1 id=a-7\n"
	    "1 2 3 4 5 6 7 8";              /* no final newline */
	struct stream s;

	open_text(&s, text, sizeof text - 1);
	CHECK(next(&s) == 1, "first record");
	CHECK(s.rec.type == NULL && s.rec.nrows == 3 && s.rec.ncols == 2,
	    "3 rows of 2, no header");
	CHECK(s.rec.num[2] == 3 && s.rec.num[5] == 6, "values");
	CHECK(s.rec.line == 3 && s.rec.rowline[2] == 6, "line numbers");
	CHECK(next(&s) == 1, "second record");
	CHECK(s.rec.type && strcmp(s.rec.type, "cubic") == 0, "type word");
	CHECK(s.rec.nattr == 2 && strcmp(loft_attr(&s.rec, "id"), "a-7") == 0
	    && strcmp(loft_attr(&s.rec, "closed"), "1") == 0, "attributes");
	CHECK(s.rec.nrows == 1 && s.rec.ncols == 8 && s.rec.num[7] == 8,
	    "unterminated last line");
	CHECK(next(&s) == 0, "end of stream");
	close_text(&s);

	open_text(&s, "# only comments\n\n\n# more\n", 25);
	CHECK(next(&s) == 0, "a stream of comments holds no record");
	close_text(&s);

	/* a NUL in a comment between records is reported; nothing is lost */
	open_text(&s, "1 2\n\n# \0\n3 4\n", 13);
	CHECK(next(&s) == 1 && s.rec.num[0] == 1, "before the NUL");
	CHECK(next(&s) == LOFT_READ_BAD && s.err.line == 3, "the NUL line");
	CHECK(next(&s) == 1 && s.rec.num[0] == 3, "after the NUL");
	close_text(&s);
}

/* Each bad record is reported at its line, and the good record after it
 * still reads. */
static void
test_reader_bad(void)
{
	static const struct { const char *text; long line; const char *says; }
	cases[] = {
		{ "1 2\nnan 3\n", 2, "not a number" },
		{ "1 2\n3 inf\n", 2, "not a number" },
		{ "1 2\n3 1e400\n", 2, "out of range" },
		{ "1 2\n3 4 5\n", 2, "more than 2 numbers" },
		{ "1 2 3\n3 4\n", 2, "has 2 numbers" },
		{ "1 2\n3 4x\n", 2, "not a number" },
		{ "1 2\npoints\n", 2, "header line inside a record" },
		{ "cubic a=1 a=2\n", 1, "given twice" },
		{ "cubic closed\n", 1, "bad attribute" },
		{ "cubic =1\n", 1, "bad attribute" },
		{ "cub!c\n", 1, "bad record type" },
		{ "cubic x=\xff\n", 1, "bad attribute" },
		{ "1 2\n3\0 4\n", 2, "NUL byte" },
	};

	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		char text[128];
		size_t len;
		struct stream s;
		int r;

		/* the case (which may hold a NUL), then a good record */
		len = strlen(cases[i].text);
		if (i == sizeof cases / sizeof cases[0] - 1)
			len = 9;       /* the text holds a NUL */
		memcpy(text, cases[i].text, len);
		memcpy(text + len, "5 6\n\n7 8\n", 9);
		open_text(&s, text, len + 9);
		r = next(&s);
		CHECK(r == LOFT_READ_BAD && s.err.line == cases[i].line &&
		    strstr(s.err.msg, cases[i].says) != NULL,
		    "case %zu: got %d at line %ld: %s", i, r, s.err.line,
		    s.err.msg);
		r = next(&s);
		CHECK(r == 1 && s.rec.nrows == 1 && s.rec.num[0] == 7,
		    "case %zu: the next record survives", i);
		close_text(&s);
	}
}

/* ------------------------------------------------------------------ */
/* cubic segments */

/* Eq. 7 meets its definition: P(0) = P_A, P(1) = P_B, P'(0) = P'_A,
 * P'(1) = P'_B, and P''' is constant: 6(P'_A + P'_B - 2(P_B - P_A)). */
static void
test_cubic_ends(void)
{
	double seg[12] = { 1, 2, 3, 4, -1, 5, 0.5, 2, -3, 7, 1, 0.25 };
	double p[3], d1[3], d2[3], e2[3];

	loft_cubic_eval(seg, 3, 0, p, d1, d2);
	for (int k = 0; k < 3; k++)
		CHECK(p[k] == seg[k] && d1[k] == seg[6 + k], "u=0, k=%d", k);
	loft_cubic_eval(seg, 3, 1, p, d1, e2);
	for (int k = 0; k < 3; k++) {
		NEAR(p[k], seg[3 + k], 1e-15, "P(1)");
		NEAR(d1[k], seg[9 + k], 1e-15, "P'(1)");
		NEAR(e2[k] - d2[k], 6 * (seg[6 + k] + seg[9 + k] -
		    2 * (seg[3 + k] - seg[k])), 1e-13, "P'''");
	}
}

/* Eq. 2 equals the cross-product form P' x (P'' x P') / (P'.P')^2. */
static void
test_curvature_cross(void)
{
	unsigned s = 12345;

	for (int t = 0; t < 1000; t++) {
		double a[3], b[3], kn[3], bxa[3], ref[3], aa;

		for (int k = 0; k < 3; k++) {
			s = s * 1103515245 + 12345;
			a[k] = (double)(s >> 8 & 0xffff) / 0x8000 - 1;
			s = s * 1103515245 + 12345;
			b[k] = (double)(s >> 8 & 0xffff) / 0x8000 - 1;
		}
		aa = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
		if (aa < 1e-3)
			continue;
		bxa[0] = b[1] * a[2] - b[2] * a[1];
		bxa[1] = b[2] * a[0] - b[0] * a[2];
		bxa[2] = b[0] * a[1] - b[1] * a[0];
		ref[0] = (a[1] * bxa[2] - a[2] * bxa[1]) / (aa * aa);
		ref[1] = (a[2] * bxa[0] - a[0] * bxa[2]) / (aa * aa);
		ref[2] = (a[0] * bxa[1] - a[1] * bxa[0]) / (aa * aa);
		CHECK(loft_curvature_vector(a, b, 3, kn) == 0, "defined");
		for (int k = 0; k < 3; k++)
			NEAR(kn[k], ref[k], 1e-9 * (1 + fabs(ref[k])), "eq. 2");
	}
	{
		double z[2] = { 0, 0 }, b[2] = { 1, 0 }, kn[2];
		CHECK(loft_curvature_vector(z, b, 2, kn) == LOFT_EGEOM,
		    "P' = 0 has no curvature");
	}
}

/*
 * loft_joint_turn: three segments, each with both tangents along one
 * direction (angle 0, theta, pi) but of unlike lengths (the turn is of
 * the directions): at joint 1 the tangent turns by theta, at joint 2 by
 * pi - theta, and round the end of the closed curve by pi.  Angles
 * from 1e-9 (where acos of the dot product gives 0) to near pi; in
 * space, the same with y split evenly between y and z.
 */
static void
test_joint_turn(void)
{
	static const double th[] = { 1e-9, 1e-4, 0.1745, 1, 2, 3.1 };

	for (size_t t = 0; t < sizeof th / sizeof th[0]; t++) {
		double seg[3][8] = { { 0 } }, sp[3][12] = { { 0 } };
		double a[3] = { 0, th[t], M_PI };

		for (int j = 0; j < 3; j++) {
			double c = cos(a[j]), s = sin(a[j]);

			seg[j][4] = (j + 2) * c;        /* P'_A */
			seg[j][5] = (j + 2) * s;
			seg[j][6] = (5 - j) * c;        /* P'_B */
			seg[j][7] = (5 - j) * s;
			sp[j][6] = seg[j][4];
			sp[j][7] = sp[j][8] = seg[j][5] / sqrt(2);
			sp[j][9] = seg[j][6];
			sp[j][10] = sp[j][11] = seg[j][7] / sqrt(2);
		}
		NEAR(loft_joint_turn(seg[0], 3, 2, 1, 1), th[t],
		    1e-12 * th[t], "turn at joint 1");
		NEAR(loft_joint_turn(seg[0], 3, 2, 1, 2), M_PI - th[t],
		    1e-12, "turn at joint 2");
		NEAR(loft_joint_turn(seg[0], 3, 2, 1, 0), M_PI, 1e-12,
		    "turn round the end");
		NEAR(loft_joint_turn(sp[0], 3, 3, 1, 1), th[t],
		    1e-12 * th[t], "turn in space");
		CHECK(loft_joint_turn(seg[0], 3, 2, 0, 0) == 0,
		    "an open curve's start");
		CHECK(loft_joint_turn(seg[0], 3, 2, 1, 3) == 0, "no joint 3");
		seg[0][6] = seg[0][7] = 0;
		CHECK(loft_joint_turn(seg[0], 3, 2, 1, 1) == 0,
		    "a zero tangent");
	}
}

/*
 * Eq. 8: chord from A = (-W/2, 0) to B = (W/2, 0), tangents at angle theta
 * to it.  The circular arc through A and B with those tangents has radius
 * R = W / (2 sin theta) and its midpoint Q at height R (1 - cos theta) =
 * (W/2) tan(theta/2).  The symmetric cubic with |P'_A| = |P'_B| = 2W/(1 +
 * cos theta) has P(1/2) = (P_A + P_B)/2 + (P'_A - P'_B)/8, so it passes
 * through Q.
 */
static void
test_eq8_midpoint(void)
{
	for (double deg = 5; deg < 180; deg += 5) {
		double th = deg * M_PI / 180, W = 3;
		double chord[2] = { W, 0 };
		double ta[2] = { cos(th), sin(th) }, tb[2] = { cos(th), -sin(th) };
		double ma, mb, seg[8], p[2];

		CHECK(loft_normalise(chord, ta, tb, 2, 2.0 / 3, &ma, &mb) == 0,
		    "normalise at %g degrees", deg);
		NEAR(ma, 2 * W / (1 + cos(th)), 1e-13 * ma, "eq. 8 |P'_A|");
		NEAR(mb, ma, 1e-13 * ma, "symmetric");
		seg[0] = -W / 2, seg[1] = 0, seg[2] = W / 2, seg[3] = 0;
		seg[4] = ma * ta[0], seg[5] = ma * ta[1];
		seg[6] = mb * tb[0], seg[7] = mb * tb[1];
		loft_cubic_eval(seg, 2, 0.5, p, NULL, NULL);
		NEAR(p[0], 0, 1e-12, "Q.x");
		NEAR(p[1], W / 2 * tan(th / 2), 1e-13 * (1 + p[1]), "Q.y");
	}
}

/* Eq. 9: where the tangent at A makes the larger angle with the chord,
 * the curve leaves A faster: |P'_A| < |P'_B| (section 4.1); and in 3-D
 * only the angles count. */
static void
test_eq9_asymmetric(void)
{
	double chord[3] = { 2, 0, 0 }, ma, mb, ma3, mb3;
	double ta[3] = { cos(1.0), sin(1.0), 0 }, tb[3] = { cos(0.3),
	    -sin(0.3), 0 };
	double ta3[3] = { cos(1.0), 0, sin(1.0) };

	CHECK(loft_normalise(chord, ta, tb, 2, 2.0 / 3, &ma, &mb) == 0, "ok");
	CHECK(ma < mb, "|P'_A| %g < |P'_B| %g", ma, mb);
	NEAR(ma, 4 / (1 + 2.0 / 3 * cos(0.3) + 1.0 / 3 * cos(1.0)), 1e-14,
	    "eq. 9 |P'_A| by hand");
	CHECK(loft_normalise(chord, ta3, tb, 3, 2.0 / 3, &ma3, &mb3) == 0,
	    "3-D");
	NEAR(ma3, ma, 1e-14, "rotating a tangent about the chord");
	{
		double back[3] = { -1, 0, 0 };
		CHECK(loft_normalise(chord, back, back, 3, 2.0 / 3, &ma, &mb) ==
		    LOFT_EGEOM, "both tangents back along the chord");
	}
}

/* The estimated end tangent of an open curve is the circle's tangent. */
static void
test_end_tangent(void)
{
	struct loft_error err;
	double a[2], b[2], c[2], t[2];
	double phi0 = 0.4, step = 0.3, R = 5;

	a[0] = R * cos(phi0), a[1] = R * sin(phi0);
	b[0] = R * cos(phi0 + step), b[1] = R * sin(phi0 + step);
	c[0] = R * cos(phi0 + 2.5 * step), c[1] = R * sin(phi0 + 2.5 * step);
	CHECK(loft_end_tangent(a, b, c, 2, t, &err) == 0, "circle");
	NEAR(t[0], -sin(phi0), 1e-12, "tangent x");
	NEAR(t[1], cos(phi0), 1e-12, "tangent y");
	c[0] = 3, c[1] = 0, b[0] = 1, b[1] = 0, a[0] = a[1] = 0;
	CHECK(loft_end_tangent(a, b, c, 2, t, &err) == 0 && t[0] == 1 &&
	    t[1] == 0, "collinear: the chord");
	CHECK(loft_end_tangent(a, b, NULL, 2, t, &err) == 0 && t[0] == 1,
	    "two knots: the chord");
	CHECK(loft_end_tangent(a, a, NULL, 2, t, &err) == LOFT_EGEOM,
	    "coincident knots");
}

/* ------------------------------------------------------------------ */
/* the baselines */

/*
 * Ferguson on a regular n-gon P_k = R(cos k phi, sin k phi): by symmetry
 * m_k = c R (-sin k phi, cos k phi), and m_{k-1} + m_{k+1} = 2 cos(phi) m_k,
 * so the row m_{k-1} + 4 m_k + m_{k+1} = 3 (P_{k+1} - P_{k-1}) gives
 * c (4 + 2 cos phi) = 6 sin phi.  Chord-length intervals are all equal
 * here, so the segments are the same.
 */
static void
test_ferguson_polygon(void)
{
	enum { N = 6 };
	double p[2 * N], seg[8 * N], R = 2, phi = 2 * M_PI / N;
	double c = 6 * sin(phi) / (4 + 2 * cos(phi));
	struct loft_fit_opts o;
	struct loft_error err;

	for (int k = 0; k < N; k++)
		p[2 * k] = R * cos(k * phi), p[2 * k + 1] = R * sin(k * phi);
	loft_fit_defaults(&o);
	for (int m = LOFT_FERGUSON; m <= LOFT_CHORD; m++) {
		o.method = m;
		CHECK(loft_fit(&o, p, N, 2, seg, NULL, &err) == 0, "fit %d", m);
		for (int k = 0; k < N; k++) {
			NEAR(seg[8 * k + 4], -c * R * sin(k * phi), 1e-12, "m.x");
			NEAR(seg[8 * k + 5], c * R * cos(k * phi), 1e-12, "m.y");
		}
	}
}

/* Open baselines on knots 0, 1, 3 of the x axis with tangents along it.
 * Chord intervals: unit speed is the solution, so the middle segment is
 * P(u) = 1 + 2u.  Uniform intervals (h = 1) on 0, 1, 2 likewise give
 * m = 1 everywhere: m_0 + 4 m_1 + m_2 = 3 (P_2 - P_0) = 6. */
static void
test_baselines_open(void)
{
	double p[6] = { 0, 0, 1, 0, 3, 0 }, q[6] = { 0, 0, 1, 0, 2, 0 };
	double seg[16], x[2];
	struct loft_fit_opts o;
	struct loft_error err;

	loft_fit_defaults(&o);
	o.closed = 0;
	o.method = LOFT_CHORD;
	CHECK(loft_fit(&o, p, 3, 2, seg, NULL, &err) == 0, "chord");
	loft_cubic_eval(seg + 8, 2, 0.5, x, NULL, NULL);
	NEAR(x[0], 2, 1e-14, "chord: middle of segment 2");
	NEAR(seg[8 + 4], 2, 1e-14, "chord: P'_A of segment 2");
	o.method = LOFT_FERGUSON;
	CHECK(loft_fit(&o, q, 3, 2, seg, NULL, &err) == 0, "ferguson");
	NEAR(seg[6], 1, 1e-14, "ferguson: P'_B of segment 1");
	NEAR(seg[7], 0, 1e-14, "ferguson: straight");
}

/*
 * loft_fit_crosses on polygons drawn as straight cubic pieces, whose
 * crossings are known by construction: a pentagon either way round
 * (star-shaped, none), the pentagram through the same points (round its
 * centre twice with its angle always rising, five crossings), a bow tie
 * (its sides cross at 0.4 and 0.6 of them), and a U that is simple but
 * not star-shaped about its centre.
 */
static void
polygon_segments(const double (*v)[2], const int *order, int n, double *seg)
{
	for (int i = 0; i < n; i++) {
		const double *a = v[order[i]], *b = v[order[(i + 1) % n]];
		double *s = seg + 8 * i;

		for (int k = 0; k < 2; k++) {
			s[k] = a[k];
			s[2 + k] = b[k];
			s[4 + k] = s[6 + k] = b[k] - a[k];
		}
	}
}

/*
 * loft_fold_crosses on the two sides of a needle tip at the origin:
 * side a along y = x^2 / 100, side b along the line y = 0.05 x, which
 * a crosses at x = 5 (the fourth edge of each, sampled every 1.5); c
 * along y = 0.2 x stays above a as far as x = 20, and meets it only at
 * the tip.
 */
static void
test_fold(void)
{
	double a[2 * 8], b[2 * 8], c[2 * 8];

	for (int i = 0; i < 8; i++) {
		double x = 1.5 * i;

		a[2 * i] = b[2 * i] = c[2 * i] = x;
		a[2 * i + 1] = x * x / 100;
		b[2 * i + 1] = 0.05 * x;
		c[2 * i + 1] = 0.2 * x;
	}
	CHECK(loft_fold_crosses(a, b, 8) == 1, "fold: sides cross at x = 5");
	CHECK(loft_fold_crosses(b, a, 8) == 1, "fold: either way round");
	CHECK(loft_fold_crosses(a, c, 8) == 0, "fold: sides apart");
	CHECK(loft_fold_crosses(a, a, 8) == 0, "fold: one side twice");
	CHECK(loft_fold_crosses(a, b, 1) == 0, "fold: one point each");
}

/*
 * A straight segment into a corner at the origin, and a cubic leaving
 * it nearly reversed (tangent 10, 0.05): its y is 0.05 u - 15 u^2 near
 * u = 0, so it crosses the straight one at u = 1/300, x = 0.033, within
 * the first edges either side of the joint; leaving at 10, -0.05 it
 * stays below.  Open, and closed by a third segment back.
 */
static void
test_fold_joint(void)
{
	double seg[3 * 8] = {
		10, 0, 0, 0, -10, 0, -10, 0,
		0, 0, 2, -5, 10, 0.05, 0, -10,
		2, -5, 10, 0, 8, 5, 8, 5,
	};

	CHECK(loft_fit_crosses(seg, 2, 0) == 1, "fold at a corner: crosses");
	CHECK(loft_fit_crosses(seg, 3, 1) == 1, "fold at a corner, closed");
	CHECK(loft_fold_u(0, 4, 1) == 0 && loft_fold_u(LOFT_FOLD_FINE, 4, 1) ==
	    0.125 && loft_fold_u(LOFT_FOLD_FINE + 4, 4, 1) == 1,
	    "fold samples: the joint, half a step, the reach");
	seg[13] = -0.05;
	CHECK(loft_fit_crosses(seg, 2, 0) == 0, "fold at a corner: apart");
	CHECK(loft_fit_crosses(seg, 3, 1) == 0, "fold at a corner: apart, "
	    "closed");
}

static void
test_crosses(void)
{
	static const double u[8][2] = { { 0, 0 }, { 3, 0 }, { 3, 3 }, { 2, 3 },
	    { 2, 1 }, { 1, 1 }, { 1, 3 }, { 0, 3 } };
	static const double tie[4][2] = { { 0, 0 }, { 2, 3 }, { 2, 0 },
	    { 0, 2 } };
	static const int ccw[5] = { 0, 1, 2, 3, 4 }, cw[5] = { 4, 3, 2, 1, 0 };
	static const int star[5] = { 0, 2, 4, 1, 3 };
	static const int seq[8] = { 0, 1, 2, 3, 4, 5, 6, 7 };
	double v[5][2], seg[8 * 8];

	for (int i = 0; i < 5; i++) {
		v[i][0] = 10 + 3 * cos(2 * M_PI * i / 5);
		v[i][1] = -4 + 3 * sin(2 * M_PI * i / 5);
	}
	polygon_segments((const double (*)[2])v, ccw, 5, seg);
	CHECK(loft_fit_crosses(seg, 5, 1) == 0, "pentagon: no crossing");
	polygon_segments((const double (*)[2])v, cw, 5, seg);
	CHECK(loft_fit_crosses(seg, 5, 1) == 0, "pentagon clockwise");
	polygon_segments((const double (*)[2])v, star, 5, seg);
	CHECK(loft_fit_crosses(seg, 5, 1) == 1, "pentagram: crossings");
	polygon_segments(tie, seq, 4, seg);
	CHECK(loft_fit_crosses(seg, 4, 1) == 1, "bow tie");
	polygon_segments(u, seq, 8, seg);
	CHECK(loft_fit_crosses(seg, 8, 1) == 0, "U: no crossing");
	test_fold();
	test_fold_joint();
}

/*
 * Grading (grade.c): the systems against their definitions (three
 * English sizes are an inch, 25.4 mm; three Paris points 2 cm), and a
 * 10 by 4 rectangle graded and mirrored by hand.
 */
static void
test_grade(void)
{
	const struct loft_size_system *en = loft_size_system("english");
	const struct loft_size_system *pa = loft_size_system("paris");
	const struct loft_size_system *mo = loft_size_system("mondopoint");
	double box[8] = { 0, 0, 10, 0, 10, 4, 0, 4 }, q[8];
	double tall[8] = { 0, 3, 0, 0, 4, 0, 4, 10 }, sq[4] = { 0, 0, 10, 9.6 };
	static const double grown[8] = { 0, 0, 12, 0, 12, 5, 0, 5 };
	static const double mirrored[8] = { 0, -5, 12, -5, 12, 0, 0, 0 };
	struct loft_grade_frame f;
	struct loft_error err;

	CHECK(en && pa && mo && loft_size_system("us") == NULL, "systems");
	NEAR(3 * en->length, 25.4, 1e-13, "english: 3 sizes an inch");
	NEAR(10 * en->width, 25.4, 1e-13, "english: width a tenth inch");
	NEAR(3 * pa->length, 20, 1e-13, "paris: 3 points 2 cm");
	NEAR(pa->width, 2, 1e-15, "paris: width 2 mm");
	CHECK(mo->length == 1 && mo->interval == 5, "mondopoint: mm, by 5");
	CHECK(loft_grade_frame(box, 4, -1, NULL, &f, &err) == 0 &&
	    f.axis == 0 && f.len == 10 && f.wid == 4 && f.ref[0] == 0 &&
	    f.ref[1] == 0, "frame of the box");
	CHECK(loft_grade_outline(&f, box, 4, 2, 1, 0, q, &err) == 0 &&
	    memcmp(q, grown, sizeof q) == 0, "the box 2 longer, 1 wider");
	CHECK(loft_grade_outline(&f, box, 4, 2, 1, 1, q, &err) == 0 &&
	    memcmp(q, mirrored, sizeof q) == 0, "its mirror");
	CHECK(loft_grade_outline(&f, box, 4, -10, 0, 0, q, &err) ==
	    LOFT_EGEOM, "no length left");
	CHECK(loft_grade_steps_fit(&f, 2.5, 1, &err) == 0 &&
	    loft_grade_steps_fit(&f, 2.6, 1, &err) != 0 &&
	    loft_grade_steps_fit(&f, 1, 1.1, &err) != 0, "steps a quarter");
	/* toe along y: the heel is the knot of least y, the first of two */
	CHECK(loft_grade_frame(tall, 4, -1, NULL, &f, &err) == 0 &&
	    f.axis == 1 && f.len == 10 && f.wid == 4 && f.ref[0] == 0 &&
	    f.ref[1] == 0, "frame of the tall box");
	CHECK(loft_grade_frame(sq, 2, -1, NULL, &f, &err) == LOFT_EGEOM,
	    "square within 5%%");
	CHECK(loft_grade_frame(sq, 2, 0, NULL, &f, &err) == 0, "-a x");
}

/*
 * Each row of the table of record types (tests/registry.sh checks the
 * table against loft.5's sections) against what the functions behind
 * its kinds accept, on a good record of the type: a record of a type
 * that can be a curve is one, of one that cannot is refused, and so for
 * surfaces, segments and design members.  A row added without its
 * operations fails here, and one without a good record below.
 */
static void
test_types(void)
{
	/* a good record's shape for each type: loft.5's rows of it */
	static const struct {
		const char *name;
		int ncols;
		int nrows;
	} shape[] = {
		{ "points", 2, 3 },
		{ "cubic", 8, 1 },
		{ "quartic", 10, 1 },
		{ "bezier", 2, 4 },
		{ "patch", 10, 5 },
		{ "bezier-surface", 3, 4 },
	};
	size_t n = sizeof shape / sizeof shape[0];
	double num[64] = { 0 };
	long rowline[8] = { 0 };

	CHECK(loft_type_named(NULL) == loft_type_named("points"),
	    "a record of no header is not a points record");
	CHECK(loft_type_named("curve") == NULL, "a type that is none");
	for (const struct loft_type *t = loft_types; t->name != NULL; t++) {
		size_t i = 0;
		struct loft_attr attr[3] = { { "id", "1" }, { "m", "1" },
		    { "n", "1" } };
		struct loft_record rec = { 0 };
		struct loft_curve c;
		struct loft_surface sf;
		struct loft_design d = { 0 };
		struct loft_error err;
		int is_curve, is_surface, is_member;

		while (i < n && strcmp(shape[i].name, t->name) != 0)
			i++;
		CHECK(i < n, "%s: no good record of it in tests/unit.c",
		    t->name);
		if (i == n)
			continue;
		CHECK(loft_type_named(t->name) == t, "%s: not found by name",
		    t->name);
		for (size_t k = 0; k < sizeof num / sizeof num[0]; k++)
			num[k] = (double)(k % 7) - 3;   /* no two rows alike */
		rec.type = (char *)t->name;
		rec.attr = attr;
		rec.nattr = 3;
		rec.num = num;
		rec.ncols = shape[i].ncols;
		rec.nrows = (size_t)shape[i].nrows;
		rec.rowline = rowline;
		CHECK(loft_record_is(&rec, t->kinds) &&
		    !loft_record_is(&rec, t->kinds | LOFT_KIND_MEMBER << 1),
		    "%s: loft_record_is", t->name);
		is_curve = loft_curve_from_record(&rec, &c, &err) == 0;
		is_surface = loft_surface_from_record(&rec, &sf, &err) == 0;
		is_member = loft_design_add(&d, &rec, &err) == 0;
		CHECK(is_curve == !!(t->kinds & LOFT_KIND_CURVE),
		    "%s: a curve %d", t->name, is_curve);
		CHECK(!is_curve || (t->degree == 0) ==
		    !!(t->kinds & LOFT_KIND_CONTROL), "%s: degree %d",
		    t->name, t->degree);
		CHECK(is_surface == !!(t->kinds & LOFT_KIND_SURFACE),
		    "%s: a surface %d", t->name, is_surface);
		CHECK(is_member == !!(t->kinds & LOFT_KIND_MEMBER),
		    "%s: a design member %d", t->name, is_member);
		CHECK((loft_curve_segments(&rec, &c, &err) == 0) ==
		    !!(t->kinds & LOFT_KIND_SEGMENTS), "%s: segments",
		    t->name);
		loft_design_free(&d);
	}
}

/* A normal deviate, standard, from a xorshift state (Box-Muller). */
static double
gauss(uint64_t *s)
{
	double u[2];

	for (int k = 0; k < 2; k++) {
		*s ^= *s << 13, *s ^= *s >> 7, *s ^= *s << 17;
		u[k] = ((double)(*s >> 11) + 0.5) / 9007199254740992.0;
	}
	return sqrt(-2 * log(u[0])) * cos(2 * M_PI * u[1]);
}

/*
 * loft_points_noise against the deviation drawn: 4000 points round a
 * circle of radius 1000 (and a space curve over it), each coordinate
 * off by noise of sigma 1; the median of 4000 draws is within 3% or so,
 * so 10% fails only a wrong scale (the plane's 0.6745 read in space is
 * 1.75 times high).  The scale is no matter: times 1e200, times 1e200.
 * Points on a line without noise: none (to rounding); on a circle, the
 * bend between neighbours.
 */
static void
test_points_noise(void)
{
	enum { N = 4000 };
	static double p[N * 3], q[N * 2];
	uint64_t s = 0x9e3779b97f4a7c15ULL;
	double e2, e3, eb;

	for (int i = 0; i < N; i++) {
		double t = 2 * M_PI * i / N;

		p[i * 3] = 1000 * cos(t) + gauss(&s);
		p[i * 3 + 1] = 1000 * sin(t) + gauss(&s);
		p[i * 3 + 2] = 200 * sin(3 * t) + gauss(&s);
		q[i * 2] = p[i * 3] * 1e200;
		q[i * 2 + 1] = p[i * 3 + 1] * 1e200;
	}
	e3 = loft_points_noise(p, N, 3, 1);
	NEAR(e3, 1, 0.1, "noise in space");
	for (int i = 0; i < N; i++)
		p[i * 2] = p[i * 3], p[i * 2 + 1] = p[i * 3 + 1];
	e2 = loft_points_noise(p, N, 2, 1);
	NEAR(e2, 1, 0.1, "noise in the plane");
	eb = loft_points_noise(q, N, 2, 1);
	NEAR(eb / 1e200, e2, 1e-12 * e2, "noise times 1e200");
	for (int i = 0; i < N; i++)
		p[i * 2] = 3 * i, p[i * 2 + 1] = 2 * i;
	CHECK(loft_points_noise(p, N, 2, 0) < 1e-12, "a line: %g",
	    loft_points_noise(p, N, 2, 0));
	for (int i = 0; i < N; i++)
		p[i * 2] = 1000 * cos(2 * M_PI * i / N),
		p[i * 2 + 1] = 1000 * sin(2 * M_PI * i / N);
	/* the bend between neighbours: each point's distance from their
	 * chord, 1000 (1 - cos(2 pi / N)) = 1.2337e-3, over 0.6745
	 * sqrt(1.5) */
	NEAR(loft_points_noise(p, N, 2, 1), 1.49e-3, 1e-5, "a clean circle");
	CHECK(loft_points_noise(p, 2, 2, 0) == 0, "two points");
}

int
main(void)
{
	test_parse_num();
	test_parse_list_int();
	test_format_roundtrip();
	test_reader_good();
	test_reader_bad();
	test_cubic_ends();
	test_curvature_cross();
	test_joint_turn();
	test_eq8_midpoint();
	test_eq9_asymmetric();
	test_end_tangent();
	test_ferguson_polygon();
	test_baselines_open();
	test_grade();
	test_crosses();
	test_types();
	test_points_noise();
	return check_done("unit");
}
