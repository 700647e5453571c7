/*
 * polyread: read polygons in brep, xy, wkt or Triangle poly form, check
 * that they make a valid region, and write them as a qtree(5) stream of
 * rings: outer rings counter-clockwise, holes clockwise.
 */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "qtree.h"

enum format { AUTO, BREP, XY, WKT, POLY };
enum role { UNKNOWN = -1, OUTER = 0, HOLE = 1 };

struct inring {
	const char	*file;
	long		*line;		/* input line of each vertex */
	struct point	*v;
	size_t		 n, cap;
	long		 firstline;
	int		 role;		/* as declared, or UNKNOWN */
	long		 poly;		/* declared polygon, for wkt */
	/* filled by the checks */
	double		 xmin, ymin, xmax, ymax;
	long		 parent;	/* innermost ring around it, or -1 */
	long		 depth;
};

static struct inring *rings;
static size_t nrings, ringcap;
static unsigned long long nvertices;
static int verbose;
static long npolys;

static struct point *seeds;	/* Triangle hole points */
static long *seedline;
static const char **seedfile;
static size_t nseeds;

static struct universe given;
static int havegiven, givenlevel = -1;
static const char *givenfile;
static long givenline;

struct src {
	const char	*name;
	char		*buf;
	size_t		 len;
	char		*p;
	long		 line;
};

static void
usage(void)
{
	fprintf(stderr, "usage: polyread [-v] [-f format] [-l level] "
	    "[-u x0,y0,size] [file ...]\n");
	exit(2);
}

static struct inring *
newring(const char *file, long line, int role, long poly)
{
	struct inring *r;

	if (nrings == ringcap) {
		ringcap = ringcap ? 2 * ringcap : 16;
		rings = xreallocarray(rings, ringcap, sizeof(*rings));
	}
	r = &rings[nrings++];
	memset(r, 0, sizeof(*r));
	r->file = file;
	r->firstline = line;
	r->role = role;
	r->poly = poly;
	return r;
}

static void
addvertex(struct src *s, struct inring *r, double x, double y, long line)
{
	if (isnan(x) || isnan(y) || isinf(x) || isinf(y))
		errat(s->name, line, "coordinate is not a finite number");
	if (!coordok(x) || !coordok(y))
		errat(s->name, line, "coordinate outside the supported range "
		    "(0, or 1e-100 to 1e100 in magnitude)");
	if (r->n == r->cap) {
		r->cap = r->cap ? 2 * r->cap : 16;
		r->v = xreallocarray(r->v, r->cap, sizeof(*r->v));
		r->line = xreallocarray(r->line, r->cap, sizeof(*r->line));
	}
	r->v[r->n].x = x;
	r->v[r->n].y = y;
	r->line[r->n++] = line;
	if ((++nvertices & 0xfffff) == 0 && verbose)
		progress(0, "%llu vertices read", nvertices);
}

static void
readall(struct src *s, const char *path)
{
	FILE *fp = openin(path, &s->name);
	size_t cap = 1 << 16, n;
	char *nul;

	s->buf = xmalloc(cap);
	s->len = 0;
	while ((n = fread(s->buf + s->len, 1, cap - s->len - 1, fp)) > 0) {
		s->len += n;
		if (cap - s->len - 1 == 0) {
			cap *= 2;
			s->buf = xreallocarray(s->buf, cap, 1);
		}
	}
	if (ferror(fp))
		die(1, "%s: read error: %s", s->name, strerror(errno));
	if (fp != stdin)
		fclose(fp);
	s->buf[s->len] = '\0';
	if ((nul = memchr(s->buf, '\0', s->len)) != NULL) {
		long line = 1;
		char *q;

		for (q = s->buf; q < nul; q++)
			line += *q == '\n';
		errat(s->name, line, "NUL byte in input");
	}
	s->p = s->buf;
	s->line = 1;
}

/* Token scanner for brep, poly and wkt: '#' starts a comment. */
static int
skipspace(struct src *s)
{
	for (;;) {
		if (*s->p == '\n') {
			s->line++;
			s->p++;
		} else if (*s->p == ' ' || *s->p == '\t' || *s->p == '\r' ||
		    *s->p == '\f' || *s->p == '\v') {
			s->p++;
		} else if (*s->p == '#') {
			while (*s->p != '\n' && *s->p != '\0')
				s->p++;
		} else
			return *s->p != '\0';
	}
}

/* The line of the last thing read, for messages about a premature end. */
static long
lastline(const struct src *s)
{
	const char *p = s->p;
	long line = s->line;

	while (p > s->buf && isspace((unsigned char)p[-1]))
		line -= *--p == '\n';
	return line;
}

static void
badtoken(struct src *s, const char *what)
{
	char tok[40];
	size_t n = 0;

	while (s->p[n] != '\0' && !isspace((unsigned char)s->p[n]) &&
	    n < sizeof(tok) - 4)
		n++;
	memcpy(tok, s->p, n);
	strcpy(tok + n, s->p[n] && !isspace((unsigned char)s->p[n]) ?
	    "..." : "");
	errat(s->name, s->line, "%s: %s", what, tok);
}

static double
number(struct src *s, const char *what)
{
	const char *end;
	double v;
	int rc;

	if (!skipspace(s))
		errat(s->name, lastline(s), "input ends where %s was expected",
		    what);
	if ((rc = parsereal(s->p, &end, &v)) == -2)
		badtoken(s, "number out of range");
	if (rc < 0 || (*end != '\0' && !isspace((unsigned char)*end) &&
	    *end != '#' && *end != ',' && *end != ')'))
		badtoken(s, "not a number");
	s->p = (char *)end;
	return v;
}

static long long
integer(struct src *s, const char *what, long long lo, long long hi)
{
	long line;
	double v;

	skipspace(s);
	line = s->line;
	v = number(s, what);
	if (v != floor(v) || v < (double)lo || v > (double)hi)
		errat(s->name, line, "%s must be an integer from %lld to %lld",
		    what, lo, hi);
	return (long long)v;
}

static void
parsebrep(struct src *s)
{
	long long nv, nh, i;
	struct inring *r;
	double cx[4], cy[4], xmin, xmax, ymin, ymax, w, h;
	long uline;
	int level;

	nv = integer(s, "number of polygon vertices", 3, (long long)1 << 50);
	nh = integer(s, "number of hole vertices", 0, (long long)1 << 50);
	if (nh > 0 && nh < 3)
		errat(s->name, s->line, "a hole needs at least 3 vertices");
	level = integer(s, "tree level", 0, QT_MAXLEVEL);
	skipspace(s);
	r = newring(s->name, s->line, OUTER, npolys);
	for (i = 0; i < nv; i++) {
		double x, y;
		long line;

		if (!skipspace(s))
			errat(s->name, lastline(s), "input ends after %lld of %lld "
			    "polygon vertices", i, nv);
		line = s->line;
		x = number(s, "x");
		y = number(s, "y");
		addvertex(s, r, x, y, line);
	}
	if (nh > 0) {
		skipspace(s);
		r = newring(s->name, s->line, HOLE, npolys);
		for (i = 0; i < nh; i++) {
			double x, y;
			long line;

			if (!skipspace(s))
				errat(s->name, lastline(s), "input ends after %lld "
				    "of %lld hole vertices", i, nh);
			line = s->line;
			x = number(s, "x");
			y = number(s, "y");
			addvertex(s, r, x, y, line);
		}
	}
	npolys++;
	skipspace(s);
	uline = s->line;
	for (i = 0; i < 4; i++) {
		if (!skipspace(s))
			errat(s->name, lastline(s), "input ends after %lld of the "
			    "4 universe corners", i);
		cx[i] = number(s, "universe x");
		cy[i] = number(s, "universe y");
	}
	if (skipspace(s))
		badtoken(s, "data after the universe corners");
	xmin = xmax = cx[0];
	ymin = ymax = cy[0];
	for (i = 1; i < 4; i++) {
		xmin = fmin(xmin, cx[i]);
		xmax = fmax(xmax, cx[i]);
		ymin = fmin(ymin, cy[i]);
		ymax = fmax(ymax, cy[i]);
	}
	for (i = 0; i < 4; i++) {
		long long j;
		int seen = 0;

		if ((cx[i] != xmin && cx[i] != xmax) ||
		    (cy[i] != ymin && cy[i] != ymax))
			errat(s->name, uline, "universe corners do not form an "
			    "axis-aligned square");
		for (j = 0; j < 4; j++)
			seen += cx[j] == cx[i] && cy[j] == cy[i];
		if (seen != 1)
			errat(s->name, uline, "universe corners repeat a "
			    "corner");
	}
	w = xmax - xmin;
	h = ymax - ymin;
	if (w <= 0 || fabs(w - h) > 1e-9 * fmax(w, h))
		errat(s->name, uline, "universe corners do not form a square "
		    "(%g wide, %g high)", w, h);
	if (havegiven)
		errat(s->name, uline, "a second universe (the first came from "
		    "%s)", givenfile);
	given.x0 = xmin;
	given.y0 = ymin;
	given.size = fmax(w, h);
	havegiven = 1;
	givenfile = s->name;
	givenline = uline;
	givenlevel = level;
}

static double
xynumber(struct src *s, const char *q, const char **end)
{
	double v;
	int rc = parsereal(q, end, &v);

	if (rc == -2)
		badtoken(s, "number out of range");
	if (rc < 0 || !(isspace((unsigned char)**end) || **end == '\0'))
		badtoken(s, "not a number");
	return v;
}

static void
parsexy(struct src *s)
{
	struct inring *r = NULL;
	char *p = s->buf, *eol;
	long line = 0;

	for (; *p != '\0'; p = *eol ? eol + 1 : eol) {
		const char *q, *end;
		double x, y;

		line++;
		eol = strchr(p, '\n');
		if (eol == NULL)
			eol = p + strlen(p);
		for (q = p; q < eol && (*q == ' ' || *q == '\t' || *q == '\r');
		    q++)
			;
		if (q == eol) {
			r = NULL;	/* a blank line ends the ring */
			continue;
		}
		if (*q == '#')
			continue;
		s->line = line;
		s->p = (char *)q;
		x = xynumber(s, q, &end);
		for (q = end; *q == ' ' || *q == '\t'; q++)
			;
		if (q == end || q == eol || *q == '\r')
			errat(s->name, line, "expected two numbers, x y");
		s->p = (char *)q;
		y = xynumber(s, q, &end);
		for (q = end; q < eol && isspace((unsigned char)*q); q++)
			;
		if (q != eol)
			errat(s->name, line, "expected two numbers, x y");
		if (r == NULL)
			r = newring(s->name, line, UNKNOWN, -1);
		addvertex(s, r, x, y, line);
	}
}

static int
keyword(struct src *s, const char *word)
{
	size_t n = strlen(word);

	if (skipspace(s) && strncasecmp(s->p, word, n) == 0 &&
	    !isalnum((unsigned char)s->p[n]) && s->p[n] != '_') {
		s->p += n;
		return 1;
	}
	return 0;
}

static void
punct(struct src *s, int c)
{
	char what[24];

	if (!skipspace(s) || *s->p != c) {
		snprintf(what, sizeof(what), "expected '%c'", c);
		if (*s->p == '\0')
			errat(s->name, lastline(s), "input ends: %s", what);
		badtoken(s, what);
	}
	s->p++;
}

static int
peek(struct src *s, int c)
{
	return skipspace(s) && *s->p == c;
}

static void
wktring(struct src *s, int role, long poly)
{
	struct inring *r;
	long line;

	if (keyword(s, "EMPTY"))
		return;
	punct(s, '(');
	r = newring(s->name, s->line, role, poly);
	do {
		double x, y;

		skipspace(s);
		line = s->line;
		x = number(s, "x");
		y = number(s, "y");
		if (peek(s, '-') || (skipspace(s) && (isdigit((unsigned char)
		    *s->p) || *s->p == '.' || *s->p == '+')))
			errat(s->name, s->line, "three or more coordinates per "
			    "point: only x y is supported");
		addvertex(s, r, x, y, line);
	} while (peek(s, ',') && (s->p++, 1));
	punct(s, ')');
	if (r->n < 2 || r->v[0].x != r->v[r->n - 1].x ||
	    r->v[0].y != r->v[r->n - 1].y)
		errat(s->name, line, "ring is not closed (the last point must "
		    "repeat the first)");
	if (r->n < 4)
		errat(s->name, line, "ring has fewer than 4 points");
}

static void
wktpolygon(struct src *s)
{
	size_t first = nrings;
	int k = 0;

	if (keyword(s, "EMPTY"))
		return;
	punct(s, '(');
	do {
		size_t before = nrings;

		wktring(s, k == 0 ? OUTER : HOLE, npolys);
		if (k == 0 && nrings == before && !peek(s, ')')) {
			/* an empty shell may only have empty holes */
			while (peek(s, ',') && (s->p++, 1))
				if (!keyword(s, "EMPTY"))
					errat(s->name, s->line, "polygon with "
					    "an empty shell has a hole");
			break;
		}
		k++;
	} while (peek(s, ',') && (s->p++, 1));
	punct(s, ')');
	if (nrings > first)
		npolys++;
}

static void
parsewkt(struct src *s)
{
	while (skipspace(s)) {
		if (keyword(s, "MULTIPOLYGON")) {
			if (keyword(s, "Z") || keyword(s, "M") ||
			    keyword(s, "ZM"))
				errat(s->name, s->line, "Z and M coordinates "
				    "are not supported");
			if (keyword(s, "EMPTY"))
				continue;
			punct(s, '(');
			do
				wktpolygon(s);
			while (peek(s, ',') && (s->p++, 1));
			punct(s, ')');
		} else if (keyword(s, "POLYGON")) {
			if (keyword(s, "Z") || keyword(s, "M") ||
			    keyword(s, "ZM"))
				errat(s->name, s->line, "Z and M coordinates "
				    "are not supported");
			wktpolygon(s);
		} else
			badtoken(s, "expected POLYGON or MULTIPOLYGON");
		if (peek(s, ';'))
			s->p++;
	}
}

struct seg {
	long	a, b;
	long	line;
};

static void
parsepoly(struct src *s)
{
	long long nv, nattr, nbm, nseg, nsbm, nholes, i, base = 0, j;
	struct point *pt = NULL;
	long *ptline = NULL, *deg, *adj, *used;
	struct seg *seg = NULL;
	size_t cap = 0;

	nv = integer(s, "number of vertices", 0, (long long)1 << 40);
	if (nv == 0)
		errat(s->name, s->line, "vertices in a separate .node file are "
		    "not supported");
	integer(s, "dimension", 2, 2);
	nattr = integer(s, "number of attributes", 0, 1000);
	nbm = integer(s, "number of boundary markers", 0, 1);
	for (i = 0; i < nv; i++) {
		long long id;

		if (!skipspace(s))
			errat(s->name, lastline(s), "input ends after %lld of %lld "
			    "vertices", i, nv);
		id = integer(s, "vertex number", 0, (long long)1 << 40);
		if (i == 0)
			base = id;
		if (id != base + i)
			errat(s->name, s->line, "vertex %lld where %lld was "
			    "expected", id, base + i);
		if ((size_t)i == cap) {
			cap = cap ? 2 * cap : 64;
			pt = xreallocarray(pt, cap, sizeof(*pt));
			ptline = xreallocarray(ptline, cap, sizeof(*ptline));
		}
		ptline[i] = s->line;
		pt[i].x = number(s, "x");
		pt[i].y = number(s, "y");
		for (j = 0; j < nattr + nbm; j++)
			number(s, "attribute or boundary marker");
	}
	nseg = integer(s, "number of segments", 0, (long long)1 << 40);
	nsbm = integer(s, "number of segment boundary markers", 0, 1);
	cap = 0;
	for (i = 0; i < nseg; i++) {
		if (!skipspace(s))
			errat(s->name, lastline(s), "input ends after %lld of %lld "
			    "segments", i, nseg);
		integer(s, "segment number", 0, (long long)1 << 40);
		if ((size_t)i == cap) {
			cap = cap ? 2 * cap : 64;
			seg = xreallocarray(seg, cap, sizeof(*seg));
		}
		seg[i].line = s->line;
		seg[i].a = integer(s, "endpoint", base, base + nv - 1) - base;
		seg[i].b = integer(s, "endpoint", base, base + nv - 1) - base;
		if (nsbm)
			number(s, "boundary marker");
		if (seg[i].a == seg[i].b)
			errat(s->name, seg[i].line, "segment joins a vertex to "
			    "itself");
	}
	if (skipspace(s)) {
		nholes = integer(s, "number of holes", 0, (long long)1 << 40);
		for (i = 0; i < nholes; i++) {
			if (!skipspace(s))
				errat(s->name, lastline(s), "input ends after %lld "
				    "of %lld holes", i, nholes);
			integer(s, "hole number", 0, (long long)1 << 40);
			seeds = xreallocarray(seeds, nseeds + 1,
			    sizeof(*seeds));
			seedline = xreallocarray(seedline, nseeds + 1,
			    sizeof(*seedline));
			seedfile = xreallocarray(seedfile, nseeds + 1,
			    sizeof(*seedfile));
			seedline[nseeds] = s->line;
			seedfile[nseeds] = s->name;
			seeds[nseeds].x = number(s, "x");
			seeds[nseeds].y = number(s, "y");
			nseeds++;
		}
	}
	if (skipspace(s)) {
		long long nreg = integer(s, "number of regions", 0,
		    (long long)1 << 40);

		for (i = 0; i < nreg; i++) {
			if (!skipspace(s))
				errat(s->name, lastline(s), "input ends after %lld "
				    "of %lld regions", i, nreg);
			integer(s, "region number", 0, (long long)1 << 40);
			number(s, "x");
			number(s, "y");
			number(s, "attribute");
			/* the area constraint is optional */
			while (*s->p == ' ' || *s->p == '\t' || *s->p == '\r')
				s->p++;
			if (*s->p != '\n' && *s->p != '#' && *s->p != '\0')
				number(s, "maximum area");
		}
	}
	if (skipspace(s))
		badtoken(s, "data after the regions");
	/* Rings from segments: every vertex on a segment has two. */
	deg = xreallocarray(NULL, nv, sizeof(*deg));
	adj = xreallocarray(NULL, 2 * nv, sizeof(*adj));
	used = xreallocarray(NULL, nseg ? nseg : 1, sizeof(*used));
	memset(deg, 0, nv * sizeof(*deg));
	for (i = 0; i < nseg; i++) {
		long a = seg[i].a, b = seg[i].b;

		if (deg[a] == 2 || deg[b] == 2)
			errat(s->name, seg[i].line, "vertex %lld is on more than "
			    "two segments: only rings are supported",
			    (deg[a] == 2 ? a : b) + base);
		adj[2 * a + deg[a]++] = i;
		adj[2 * b + deg[b]++] = i;
		used[i] = 0;
	}
	for (i = 0; i < nv; i++)
		if (deg[i] == 1)
			errat(s->name, ptline[i], "vertex %lld ends a chain of "
			    "segments that does not close", i + base);
	for (i = 0; i < nseg; i++) {
		struct inring *r;
		long v, e = i;

		if (used[i])
			continue;
		r = newring(s->name, seg[i].line, UNKNOWN, -1);
		v = seg[i].a;
		do {
			long w;

			used[e] = 1;
			addvertex(s, r, pt[v].x, pt[v].y, ptline[v]);
			w = seg[e].a == v ? seg[e].b : seg[e].a;
			e = adj[2 * w] == e ? adj[2 * w + 1] : adj[2 * w];
			v = w;
		} while (!used[e]);
	}
	free(deg);
	free(adj);
	free(used);
	free(pt);
	free(ptline);
	free(seg);
}

/*
 * wkt when the first word starts with a letter; otherwise the first line
 * that holds data decides: two fields make xy, four integers with the
 * second 2 make poly (Triangle's header), anything else brep.
 */
static enum format
detect(struct src *s)
{
	const char *p;
	int n = 0, ints = 0;

	s->p = s->buf;
	if (!skipspace(s))
		errat(s->name, lastline(s), "no polygon in the input");
	if (isalpha((unsigned char)*s->p))
		return WKT;
	for (p = s->p; *p != '\n' && *p != '\0' && *p != '#'; ) {
		size_t len;

		p += strspn(p, " \t\r\f\v");
		if ((len = strcspn(p, " \t\r\f\v\n#")) == 0)
			break;
		n++;
		if (strspn(p, "0123456789") == len &&
		    (n != 2 || (len == 1 && *p == '2')))
			ints++;
		p += len;
	}
	if (n == 2)
		return XY;
	return n == 4 && ints == 4 ? POLY : BREP;
}

/* Drops consecutive repeats and the closing repeat of the first vertex. */
static void
tidy(struct inring *r)
{
	size_t i, k = 0;

	for (i = 0; i < r->n; i++) {
		if (k > 0 && r->v[i].x == r->v[k - 1].x &&
		    r->v[i].y == r->v[k - 1].y)
			continue;
		r->v[k] = r->v[i];
		r->line[k++] = r->line[i];
	}
	while (k > 1 && r->v[k - 1].x == r->v[0].x && r->v[k - 1].y == r->v[0].y)
		k--;
	r->n = k;
}

/* Which rings they are, as people count them: from 1 in input order. */
static long
ringno(const struct inring *r)
{
	return (long)(r - rings) + 1;
}

static void
checkring(struct inring *r)
{
	size_t i, far = 0;
	int third = 0;

	for (i = 1; i < r->n; i++)
		if (r->v[i].x != r->v[0].x || r->v[i].y != r->v[0].y) {
			far = i;
			break;
		}
	for (i = 1; far > 0 && i < r->n && !third; i++)
		third = (r->v[i].x != r->v[0].x || r->v[i].y != r->v[0].y) &&
		    (r->v[i].x != r->v[far].x || r->v[i].y != r->v[far].y);
	if (!third)
		errat(r->file, r->firstline, "ring %ld has fewer than 3 "
		    "distinct vertices", ringno(r));
	for (i = 1; i < r->n; i++)
		if (orient2d(r->v[0].x, r->v[0].y, r->v[far].x, r->v[far].y,
		    r->v[i].x, r->v[i].y) != 0)
			break;
	if (i == r->n)
		errat(r->file, r->firstline, "ring %ld has zero area",
		    ringno(r));
	r->xmin = r->xmax = r->v[0].x;
	r->ymin = r->ymax = r->v[0].y;
	for (i = 1; i < r->n; i++) {
		r->xmin = fmin(r->xmin, r->v[i].x);
		r->xmax = fmax(r->xmax, r->v[i].x);
		r->ymin = fmin(r->ymin, r->v[i].y);
		r->ymax = fmax(r->ymax, r->v[i].y);
	}
}

/*
 * Crossings: a sweep over the vertices in (x, y) order keeps the edges that
 * the sweep line cuts in a treap, from bottom to top, placed by exact
 * orientation against the vertex at hand.  Only edges that meet at a vertex
 * or are neighbours on the sweep line are tested, so the cost does not grow
 * with how long the edges are next to their spacing.
 */
#define NONE	((size_t)-1)

struct edge {
	double		 xmin, ymin, xmax, ymax;
	long		 ring;
	size_t		 i;
	size_t		 kid[2];	/* treap children, or NONE */
	uint32_t	 pri;		/* treap heap key */
	int		 rises;		/* the sweep meets its lower end first */
};

struct touch {
	long		ring[2];
	struct point	p;
};

static struct edge *edges;
static struct touch *touches;
static size_t ntouches, touchcap;

static struct point
ep(const struct edge *e, int end)
{
	const struct inring *r = &rings[e->ring];

	return r->v[(e->i + end) % r->n];
}

static void
edgefail(const struct edge *e, const struct edge *f, const char *what,
    struct point p)
{
	const struct inring *r = &rings[e->ring], *q = &rings[f->ring];
	char px[32], py[32];

	fmtreal(px, p.x);
	fmtreal(py, p.y);
	errat(r->file, r->line[e->i], "ring %ld edge %zu (line %ld) %s ring %ld "
	    "edge %zu (line %ld) at %s %s", ringno(r), e->i + 1, r->line[e->i],
	    what, ringno(q), f->i + 1, q->line[f->i], px, py);
}

static void
addtouch(long a, long b, struct point p)
{
	if (ntouches == touchcap) {
		touchcap = touchcap ? 2 * touchcap : 64;
		touches = xreallocarray(touches, touchcap, sizeof(*touches));
	}
	touches[ntouches].ring[0] = a < b ? a : b;
	touches[ntouches].ring[1] = a < b ? b : a;
	touches[ntouches++].p = p;
}

static void
testpair(const struct edge *e, const struct edge *f)
{
	struct point a, b, c, d, p;
	int o1, o2, o3, o4, adjacent;

	if (e->xmax < f->xmin || f->xmax < e->xmin || e->ymax < f->ymin ||
	    f->ymax < e->ymin)
		return;
	a = ep(e, 0), b = ep(e, 1), c = ep(f, 0), d = ep(f, 1);
	o1 = orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
	o2 = orient2d(a.x, a.y, b.x, b.y, d.x, d.y);
	if (o1 == o2 && o1 != 0)
		return;
	o3 = orient2d(c.x, c.y, d.x, d.y, a.x, a.y);
	o4 = orient2d(c.x, c.y, d.x, d.y, b.x, b.y);
	if (o3 == o4 && o3 != 0)
		return;
	adjacent = e->ring == f->ring && ((e->i + 1) % rings[e->ring].n == f->i
	    || (f->i + 1) % rings[e->ring].n == e->i);
	if (o1 == 0 && o2 == 0) {
		/* Collinear: a shared stretch, or a single shared end. */
		int usex = e->xmin != e->xmax;
		double elo = usex ? e->xmin : e->ymin, ehi = usex ? e->xmax :
		    e->ymax, flo = usex ? f->xmin : f->ymin, fhi = usex ?
		    f->xmax : f->ymax;

		if (fmax(elo, flo) < fmin(ehi, fhi)) {
			p = fmax(elo, flo) == elo ? (usex ? (a.x < b.x ? a : b) :
			    (a.y < b.y ? a : b)) : (usex ? (c.x < d.x ? c : d) :
			    (c.y < d.y ? c : d));
			edgefail(e, f, "overlaps", p);
		}
		p = (a.x == c.x && a.y == c.y) || (a.x == d.x && a.y == d.y) ?
		    a : b;
	} else if (o1 * o2 < 0 && o3 * o4 < 0) {
		double den = (b.x - a.x) * (d.y - c.y) - (b.y - a.y) *
		    (d.x - c.x);
		double t = ((c.x - a.x) * (d.y - c.y) - (c.y - a.y) *
		    (d.x - c.x)) / den;

		p.x = a.x + t * (b.x - a.x);
		p.y = a.y + t * (b.y - a.y);
		edgefail(e, f, "crosses", p);
	} else
		p = o1 == 0 ? c : o2 == 0 ? d : o3 == 0 ? a : b;
	if (adjacent)
		return;
	if (e->ring == f->ring)
		edgefail(e, f, "touches", p);
	addtouch(e->ring, f->ring, p);
}

/* The order of the sweep's events: by x, then by y. */
static int
before(struct point a, struct point b)
{
	return a.x < b.x || (a.x == b.x && a.y < b.y);
}

static int
samepoint(struct point a, struct point b)
{
	return a.x == b.x && a.y == b.y;
}

/*
 * The end the sweep reaches first (last = 0) or last (last = 1), from the
 * bounding box, which the sweep reads far more often than the ring.
 */
static struct point
sweepend(const struct edge *e, int last)
{
	struct point p;

	p.x = last ? e->xmax : e->xmin;
	p.y = last == e->rises ? e->ymax : e->ymin;
	return p;
}

/*
 * Where p lies against an edge that the sweep line cuts while it passes p:
 * > 0 above, < 0 below, 0 on it.  A vertical edge is cut only while the
 * sweep runs up its own x, and then only between its ends, so p is on it.
 * An edge that ends at p is on it too, and saying so at once spares the
 * exact arithmetic that the orientation of a collinear triple costs.
 */
static int
side(const struct edge *t, struct point p)
{
	struct point a = sweepend(t, 0), b = sweepend(t, 1);

	if (a.x == b.x || samepoint(b, p))
		return 0;
	return orient2d(a.x, a.y, b.x, b.y, p.x, p.y);
}

/*
 * Treap priorities: the edge's number scrambled by a bijective hash, so
 * that the treap stays shallow whatever order the edges come in.
 */
static uint32_t
scramble(uint32_t x)
{
	x ^= x >> 16;
	x *= 0x85ebca6bU;
	x ^= x >> 13;
	x *= 0xc2b2ae35U;
	x ^= x >> 16;
	return x;
}

/*
 * Splits a treap into the edges with side(t, p) >= lim and the rest.  Up
 * the sweep line come the edges below p, then those through p, then those
 * above, so that two splits cut out the edges through p.
 */
static void
split(size_t t, struct point p, int lim, size_t *lo, size_t *hi)
{
	if (t == NONE)
		*lo = *hi = NONE;
	else if (side(&edges[t], p) >= lim) {
		*lo = t;
		split(edges[t].kid[1], p, lim, &edges[t].kid[1], hi);
	} else {
		*hi = t;
		split(edges[t].kid[0], p, lim, lo, &edges[t].kid[0]);
	}
}

/* Joins two treaps, every edge of lo being below every edge of hi. */
static size_t
merge(size_t lo, size_t hi)
{
	if (lo == NONE)
		return hi;
	if (hi == NONE)
		return lo;
	if (edges[lo].pri > edges[hi].pri) {
		edges[lo].kid[1] = merge(edges[lo].kid[1], hi);
		return lo;
	}
	edges[hi].kid[0] = merge(lo, edges[hi].kid[0]);
	return hi;
}

/* The lowest (dir = 0) or highest (dir = 1) edge of a treap. */
static size_t
outermost(size_t t, int dir)
{
	if (t != NONE)
		while (edges[t].kid[dir] != NONE)
			t = edges[t].kid[dir];
	return t;
}

static size_t *here;		/* the edges that hold the vertex at hand */
static size_t nhere, herecap;

static void
addhere(size_t k)
{
	if (nhere == herecap) {
		herecap = herecap ? 2 * herecap : 64;
		here = xreallocarray(here, herecap, sizeof(*here));
	}
	here[nhere++] = k;
}

static void
collect(size_t t)
{
	if (t == NONE)
		return;
	collect(edges[t].kid[0]);
	addhere(t);
	collect(edges[t].kid[1]);
}

/*
 * Orders edges that go on from p, bottom to top just past p: by the turn
 * from one's far end to the other's, exact, and right for every direction
 * the sweep allows (rightward, or straight up, which comes last).
 */
static void
sortfrom(size_t *list, size_t n, struct point p)
{
	size_t i, j, k;

	for (i = 1; i < n; i++) {
		struct point b;

		k = list[i];
		b = sweepend(&edges[k], 1);
		for (j = i; j > 0; j--) {
			struct point a = sweepend(&edges[list[j - 1]], 1);

			if (orient2d(p.x, p.y, a.x, a.y, b.x, b.y) >= 0)
				break;
			list[j] = list[j - 1];
		}
		list[j] = k;
	}
}

static void
testneighbours(size_t lo, size_t hi)
{
	if (lo != NONE && hi != NONE)
		testpair(&edges[lo], &edges[hi]);
}

/*
 * Passes the vertex p.  Every edge that holds p (ending there, passing
 * through or leaving it) is tested against every other, bottom to top in
 * each group, which records every touch at p and finds every overlap that
 * starts there.  Then the edges that leave p take the place of those that
 * end there, and the edges that become neighbours are tested: two edges
 * that cross away from any vertex are neighbours before the sweep gets
 * there (Shamos and Hoey), as long as nothing crossed before, which the
 * tests so far have made sure of.
 */
static size_t
sweepvertex(size_t root, struct point p, size_t *leave, size_t nleave)
{
	size_t below, rest, mid, above, i, j, n;

	split(root, p, 1, &below, &rest);
	split(rest, p, 0, &mid, &above);
	nhere = 0;
	collect(mid);
	sortfrom(leave, nleave, p);
	for (i = 0; i < nleave; i++)
		addhere(leave[i]);
	for (i = 0; i < nhere; i++)
		for (j = i + 1; j < nhere; j++)
			testpair(&edges[here[i]], &edges[here[j]]);
	/*
	 * What goes on past p: the edges that leave it, and at most one that
	 * passes through, as two would have crossed or overlapped.
	 */
	for (i = n = 0; i < nhere; i++)
		if (!samepoint(sweepend(&edges[here[i]], 1), p))
			here[n++] = here[i];
	sortfrom(here, n, p);
	if (n == 0)
		testneighbours(outermost(below, 1), outermost(above, 0));
	else {
		testneighbours(outermost(below, 1), here[0]);
		testneighbours(here[n - 1], outermost(above, 0));
	}
	mid = NONE;
	for (i = 0; i < n; i++) {
		edges[here[i]].kid[0] = edges[here[i]].kid[1] = NONE;
		mid = merge(mid, here[i]);
	}
	return merge(merge(below, mid), above);
}

/* A vertex: p, and k the edge from it to the next vertex of its ring. */
struct event {
	struct point	p;
	size_t		k;
};

static int
cmpevent(const void *a, const void *b)
{
	const struct event *s = a, *t = b;

	if (s->p.x != t->p.x)
		return s->p.x < t->p.x ? -1 : 1;
	if (s->p.y != t->p.y)
		return s->p.y < t->p.y ? -1 : 1;
	/* in ring order when they coincide, so that messages do not vary */
	return (s->k > t->k) - (s->k < t->k);
}

/* Vertices that coincide, of one ring or several, make one event. */
static void
sweep(size_t n)
{
	struct event *ev = xreallocarray(NULL, n, sizeof(*ev));
	size_t *leave = NULL, cap = 0, i, g, root = NONE;

	for (i = 0; i < n; i++) {
		ev[i].p = ep(&edges[i], 0);
		ev[i].k = i;
	}
	qsort(ev, n, sizeof(*ev), cmpevent);
	for (i = 0; i < n; i = g) {
		size_t nleave = 0;

		for (g = i; g < n && samepoint(ev[g].p, ev[i].p); g++) {
			size_t k = ev[g].k, prev = edges[k].i > 0 ? k - 1 :
			    k + rings[edges[k].ring].n - 1;

			if (nleave + 2 > cap) {
				cap = cap ? 2 * cap : 16;
				leave = xreallocarray(leave, cap,
				    sizeof(*leave));
			}
			/* those that end at p are in the treap already */
			if (before(ev[i].p, ep(&edges[k], 1)))
				leave[nleave++] = k;
			if (before(ev[i].p, ep(&edges[prev], 0)))
				leave[nleave++] = prev;
		}
		root = sweepvertex(root, ev[i].p, leave, nleave);
	}
	free(leave);
	free(ev);
	free(here);
	here = NULL;
	nhere = herecap = 0;
}

static long *uf;

static long
find(long x)
{
	while (uf[x] != x)
		x = uf[x] = uf[uf[x]];
	return x;
}

static long
polyof(long ring)
{
	return rings[ring].depth % 2 == 0 ? ring : rings[ring].parent;
}

struct link {
	long		poly, ring;
	struct point	p;
};

static int
cmplink(const void *a, const void *b)
{
	const struct link *s = a, *t = b;

	if (s->poly != t->poly)
		return s->poly < t->poly ? -1 : 1;
	if (s->p.x != t->p.x)
		return s->p.x < t->p.x ? -1 : 1;
	if (s->p.y != t->p.y)
		return s->p.y < t->p.y ? -1 : 1;
	return (s->ring > t->ring) - (s->ring < t->ring);
}

/*
 * A polygon's interior is connected unless its rings and the points where
 * they touch form a cycle (the OGC rule GEOS checks).  Each link joins a
 * ring to a touching point of its own polygon; a link between two nodes
 * already connected closes a cycle.
 */
static void
connectivity(void)
{
	struct link *link = xreallocarray(NULL, 2 * ntouches + 1,
	    sizeof(*link));
	size_t i, n = 0, node = nrings;

	for (i = 0; i < ntouches; i++) {
		long pa = polyof(touches[i].ring[0]);
		int m;

		if (pa != polyof(touches[i].ring[1]))
			continue;
		for (m = 0; m < 2; m++) {
			link[n].poly = pa;
			link[n].ring = touches[i].ring[m];
			link[n++].p = touches[i].p;
		}
	}
	qsort(link, n, sizeof(*link), cmplink);
	uf = xreallocarray(NULL, nrings + n + 1, sizeof(*uf));
	for (i = 0; i < nrings + n + 1; i++)
		uf[i] = i;
	for (i = 0; i < n; i++) {
		long a, b;

		if (i > 0 && cmplink(&link[i - 1], &link[i]) == 0)
			continue;
		if (i > 0 && (link[i - 1].poly != link[i].poly ||
		    link[i - 1].p.x != link[i].p.x ||
		    link[i - 1].p.y != link[i].p.y))
			node++;
		a = find(link[i].ring);
		b = find(node);
		if (a == b) {
			const struct inring *r = &rings[link[i].ring];
			char px[32], py[32];

			fmtreal(px, link[i].p.x);
			fmtreal(py, link[i].p.y);
			errat(r->file, r->firstline, "interior is disconnected: "
			    "ring %ld touches the rings around it at %s %s "
			    "and elsewhere, closing a loop", ringno(r), px, py);
		}
		uf[a] = b;
	}
	free(uf);
	free(link);
}

/*
 * Containment queries against a large ring look only at the edges in the
 * horizontal strip of the query point: a ray at height y can only cross
 * edges whose y range holds y, and those are all filed under y's strip.
 */
struct strips {
	double	 ymin, height;
	size_t	 k;
	size_t	*start;		/* edges of strip j: edge[start[j]..start[j+1]) */
	size_t	*edge;
};

static size_t
stripof(const struct strips *st, double y)
{
	double f = (y - st->ymin) / st->height;

	if (!(f > 0))
		return 0;
	return f >= (double)(st->k - 1) ? st->k - 1 : (size_t)f;
}

static void
buildstrips(const struct inring *r, struct strips *st)
{
	size_t i, j, *fill;
	double sum = 0, lim;

	/*
	 * An edge is filed under every strip it spans: with long edges (a
	 * zigzag) fewer strips keep that to about 5 entries per edge.
	 */
	for (i = 0; i < r->n; i++)
		sum += fabs(r->v[(i + 1) % r->n].y - r->v[i].y);
	lim = 4.0 * r->n * (r->ymax - r->ymin) / sum;
	st->k = r->n / 8;
	if (lim < st->k)
		st->k = lim < 1 ? 1 : (size_t)lim;
	st->ymin = r->ymin;
	st->height = (r->ymax - r->ymin) / st->k;
	st->start = xreallocarray(NULL, st->k + 1, sizeof(*st->start));
	fill = xreallocarray(NULL, st->k + 1, sizeof(*fill));
	memset(st->start, 0, (st->k + 1) * sizeof(*st->start));
	for (i = 0; i < r->n; i++) {
		struct point a = r->v[i], b = r->v[(i + 1) % r->n];
		size_t lo = stripof(st, fmin(a.y, b.y)), hi = stripof(st,
		    fmax(a.y, b.y));

		for (j = lo; j <= hi; j++)
			st->start[j + 1]++;
	}
	for (j = 0; j < st->k; j++)
		st->start[j + 1] += st->start[j];
	memcpy(fill, st->start, (st->k + 1) * sizeof(*fill));
	st->edge = xreallocarray(NULL, st->start[st->k] + 1,
	    sizeof(*st->edge));
	for (i = 0; i < r->n; i++) {
		struct point a = r->v[i], b = r->v[(i + 1) % r->n];
		size_t lo = stripof(st, fmin(a.y, b.y)), hi = stripof(st,
		    fmax(a.y, b.y));

		for (j = lo; j <= hi; j++)
			st->edge[fill[j]++] = i;
	}
	free(fill);
}

static struct strips *strips;

static int
contains(size_t ring, struct point p, struct point toward)
{
	const struct inring *r = &rings[ring];
	struct strips *st = &strips[ring];
	size_t j, s;
	int inside = 0;

	if (r->n < 64)
		return ring_contains(r->v, r->n, p, toward);
	if (st->k == 0)
		buildstrips(r, st);
	s = stripof(st, p.y);
	for (j = st->start[s]; j < st->start[s + 1]; j++) {
		size_t i = st->edge[j];

		inside ^= ray_crosses(r->v[i], r->v[(i + 1) % r->n], p,
		    toward);
	}
	return inside;
}

static int
cmpring(const void *a, const void *b)
{
	const struct inring *r = &rings[*(const size_t *)a];
	const struct inring *q = &rings[*(const size_t *)b];

	return (r->xmin > q->xmin) - (r->xmin < q->xmin);
}

static int
bboxinside(const struct inring *a, const struct inring *b)
{
	return b->xmin <= a->xmin && b->xmax >= a->xmax &&
	    b->ymin <= a->ymin && b->ymax >= a->ymax;
}

/*
 * Depth: how many rings contain it.  Parent: the deepest of those.  A sweep
 * in x keeps the rings whose x range reaches the current one, so each ring
 * is tested only against rings whose box could hold it.
 */
static void
nesting(void)
{
	size_t i, j, g, n = 0, cap = 0, nact = 0, *order, *active;
	long (*pair)[2] = NULL;

	order = xreallocarray(NULL, nrings + 1, sizeof(*order));
	active = xreallocarray(NULL, nrings + 1, sizeof(*active));
	strips = xreallocarray(NULL, nrings + 1, sizeof(*strips));
	memset(strips, 0, (nrings + 1) * sizeof(*strips));
	for (i = 0; i < nrings; i++) {
		order[i] = i;
		rings[i].depth = 0;
		rings[i].parent = -1;
	}
	qsort(order, nrings, sizeof(*order), cmpring);
	for (i = 0; i < nrings; i = g) {
		double x = rings[order[i]].xmin;
		size_t keep = 0;

		/* rings that start together may hold one another */
		for (g = i; g < nrings && rings[order[g]].xmin == x; g++)
			active[nact++] = order[g];
		for (j = 0; j < nact; j++)
			if (rings[active[j]].xmax >= x)
				active[keep++] = active[j];
		nact = keep;
		for (; i < g; i++) {
			struct inring *a = &rings[order[i]];

			for (j = 0; j < nact; j++) {
				size_t b = active[j];

				if (b == order[i] || !bboxinside(a, &rings[b]) ||
				    !contains(b, a->v[0], a->v[1]))
					continue;
				if (n == cap) {
					cap = cap ? 2 * cap : 64;
					pair = xreallocarray(pair, cap,
					    sizeof(*pair));
				}
				pair[n][0] = order[i];
				pair[n++][1] = b;
				a->depth++;
			}
		}
	}
	for (i = 0; i < n; i++) {
		struct inring *a = &rings[pair[i][0]];

		if (a->parent < 0 ||
		    rings[pair[i][1]].depth > rings[a->parent].depth)
			a->parent = pair[i][1];
	}
	for (i = 0; i < nrings; i++)
		if (strips[i].k > 0) {
			free(strips[i].start);
			free(strips[i].edge);
		}
	free(strips);
	free(pair);
	free(order);
	free(active);
}

/* Declared roles (wkt, brep) must agree with the nesting. */
static void
checkroles(void)
{
	size_t i;

	for (i = 0; i < nrings; i++) {
		struct inring *r = &rings[i], *p;

		if (r->role == UNKNOWN)
			continue;
		p = r->parent >= 0 ? &rings[r->parent] : NULL;
		if (r->role == OUTER && p != NULL && p->role != HOLE)
			errat(r->file, r->firstline, "polygon of ring %ld lies "
			    "inside polygon of ring %ld", ringno(r), ringno(p));
		if (r->role == HOLE && p != NULL && p->role == HOLE)
			errat(r->file, r->firstline, "hole ring %ld lies inside "
			    "hole ring %ld", ringno(r), ringno(p));
		if (r->role == HOLE && (p == NULL || p->poly != r->poly))
			errat(r->file, r->firstline, "hole ring %ld lies "
			    "outside its shell", ringno(r));
	}
}

static void
checkedges(void)
{
	size_t i, j, n = 0;

	for (i = 0; i < nrings; i++)
		n += rings[i].n;
	edges = xreallocarray(NULL, n, sizeof(*edges));
	n = 0;
	for (i = 0; i < nrings; i++)
		for (j = 0; j < rings[i].n; j++) {
			struct edge *e = &edges[n];
			struct point a, b;

			e->ring = i;
			e->i = j;
			a = ep(e, 0);
			b = ep(e, 1);
			e->xmin = fmin(a.x, b.x);
			e->xmax = fmax(a.x, b.x);
			e->ymin = fmin(a.y, b.y);
			e->ymax = fmax(a.y, b.y);
			e->kid[0] = e->kid[1] = NONE;
			e->pri = scramble(n);
			e->rises = before(a, b) ? a.y <= b.y : b.y <= a.y;
			n++;
		}
	sweep(n);
	free(edges);
}

/* Exact orientation of a simple ring: the turn at its lowest-left vertex. */
static int
ringsign(const struct inring *r)
{
	size_t i, m = 0;
	struct point a, b, c;

	for (i = 1; i < r->n; i++)
		if (r->v[i].x < r->v[m].x ||
		    (r->v[i].x == r->v[m].x && r->v[i].y < r->v[m].y))
			m = i;
	a = r->v[(m + r->n - 1) % r->n];
	b = r->v[m];
	c = r->v[(m + 1) % r->n];
	return orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}

static void
reverse(struct inring *r)
{
	size_t i, j;

	for (i = 0, j = r->n - 1; i < j; i++, j--) {
		struct point t = r->v[i];
		long l = r->line[i];

		r->v[i] = r->v[j];
		r->v[j] = t;
		r->line[i] = r->line[j];
		r->line[j] = l;
	}
}

/* The bounding box, squared up from its lower left corner. */
static void
defaultuniverse(struct universe *u)
{
	double xmin, ymin, xmax, ymax;
	size_t i;

	if (nrings == 0) {
		u->x0 = u->y0 = 0;
		u->size = 1;
		return;
	}
	xmin = rings[0].xmin, ymin = rings[0].ymin;
	xmax = rings[0].xmax, ymax = rings[0].ymax;
	for (i = 1; i < nrings; i++) {
		xmin = fmin(xmin, rings[i].xmin);
		ymin = fmin(ymin, rings[i].ymin);
		xmax = fmax(xmax, rings[i].xmax);
		ymax = fmax(ymax, rings[i].ymax);
	}
	u->x0 = xmin;
	u->y0 = ymin;
	u->size = fmax(xmax - xmin, ymax - ymin);
	while (u->x0 + u->size < xmax || u->y0 + u->size < ymax)
		u->size = nextafter(u->size, INFINITY);
}

static void
checkuniverse(const struct universe *u, const char *how)
{
	size_t i, j;

	for (i = 0; i < nrings; i++)
		for (j = 0; j < rings[i].n; j++) {
			struct point p = rings[i].v[j];

			if (p.x < u->x0 || p.y < u->y0 ||
			    p.x > u->x0 + u->size || p.y > u->y0 + u->size)
				errat(rings[i].file, rings[i].line[j], "vertex "
				    "lies outside the universe %s", how);
		}
}

static void
checkseeds(void)
{
	size_t i, j;

	for (i = 0; i < nseeds; i++) {
		int inside = 0;

		for (j = 0; j < nrings; j++)
			inside ^= ring_contains(rings[j].v, rings[j].n,
			    seeds[i], seeds[i]);
		if (inside)
			errat(seedfile[i], seedline[i], "hole point lies inside "
			    "the region its rings bound");
	}
}

static void
parseuniverse(const char *arg)
{
	const char *p = arg, *end;
	double v[3];
	int i;

	for (i = 0; i < 3; i++) {
		if (parsereal(p, &end, &v[i]) < 0 || !coordok(v[i]))
			die(2, "-u: expected x0,y0,size: %s", arg);
		p = end;
		if (i < 2 && *p++ != ',')
			die(2, "-u: expected x0,y0,size: %s", arg);
	}
	if (*p != '\0' || v[2] <= 0)
		die(2, "-u: expected x0,y0,size with size > 0: %s", arg);
	given.x0 = v[0];
	given.y0 = v[1];
	given.size = v[2];
}

int
main(int argc, char *argv[])
{
	enum format format = AUTO;
	struct universe u;
	const char *end;
	long long level = -1;
	size_t i;
	int ch, haveu = 0;

	setprogname_(argv[0]);
	while ((ch = getopt(argc, argv, "f:l:u:v")) != -1)
		switch (ch) {
		case 'f':
			if (strcmp(optarg, "brep") == 0)
				format = BREP;
			else if (strcmp(optarg, "xy") == 0)
				format = XY;
			else if (strcmp(optarg, "wkt") == 0)
				format = WKT;
			else if (strcmp(optarg, "poly") == 0)
				format = POLY;
			else
				die(2, "-f: unknown format %s (brep, xy, wkt, "
				    "poly)", optarg);
			break;
		case 'l':
			if (parselong(optarg, &end, &level) < 0 || *end != '\0' ||
			    level < 0 || level > QT_MAXLEVEL)
				die(2, "-l: level must be an integer from 0 to "
				    "%d: %s", QT_MAXLEVEL, optarg);
			break;
		case 'u':
			parseuniverse(optarg);
			haveu = 1;
			break;
		case 'v':
			verbose = 1;
			break;
		default:
			usage();
		}
	argc -= optind;
	argv += optind;

	for (i = 0; i == 0 || (int)i < argc; i++) {
		struct src s;
		enum format f;

		readall(&s, argc > 0 ? argv[i] : "-");
		f = detect(&s);
		if (format != AUTO)
			f = format;
		s.p = s.buf;
		s.line = 1;
		switch (f) {
		case BREP:
			parsebrep(&s);
			break;
		case XY:
			parsexy(&s);
			break;
		case WKT:
			parsewkt(&s);
			break;
		default:
			parsepoly(&s);
			break;
		}
		/* rings keep pointers to the name, not to the buffer */
		free(s.buf);
	}

	if (verbose)
		progress(1, "%llu vertices in %zu rings read", nvertices,
		    nrings);
	for (i = 0; i < nrings; i++) {
		tidy(&rings[i]);
		checkring(&rings[i]);
	}
	checkedges();
	if (verbose)
		progress(1, "no two edges cross or overlap");
	nesting();
	checkroles();
	connectivity();
	checkseeds();
	if (verbose)
		progress(1, "nesting and connectivity checked");
	if (haveu) {
		u = given;
		checkuniverse(&u, "given with -u");
	} else if (havegiven) {
		u = given;
		checkuniverse(&u, "given in the input");
	} else
		defaultuniverse(&u);
	if (level < 0)
		level = givenlevel;

	qt_header();
	qt_universe(&u);
	if (level >= 0)
		qt_level(level);
	for (i = 0; i < nrings; i++) {
		struct inring *r = &rings[i];
		struct ring out;
		int hole = r->depth % 2;

		if ((ringsign(r) > 0) == hole)
			reverse(r);
		out.id = i + 1;
		out.hole = hole;
		out.n = r->n;
		out.v = r->v;
		qt_ring(&out);
	}
	qt_end();
	if (verbose)
		progress(1, "%zu rings written", nrings);
	closeout();
	return 0;
}
