/*
 * merge.c: -m, the outputs of qtstats -s, of the shards of one tree,
 * added up into the polygon's and the tree's sums, from which main.c
 * writes the tree's figures as if it had read the whole tree.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "qtstats.h"

/*
 * -m: the sums of several inputs added up.  A partial is one -s output;
 * its head lines must be the first partial's, byte for byte.  A partial's
 * root that is a node at the end of another partial (the top of a cut,
 * qtsplit -t, lists the shards' roots as nodes) is counted once.
 */
struct claim {
	struct nodeat	 n;
	const char	*name;
	long		 lineno;
	int		 part;		/* the partial's number */
	int		 claimed;
};

static struct merge {
	struct claim	*roots, *dangling;
	size_t		 nroots, rootcap, ndangling, dangcap;
	int		 partials;
} mg;

static int
getu64(const char *s, uint64_t *v)
{
	uint64_t x = 0;

	*v = 0;
	if (*s == '\0')
		return -1;
	for (; *s >= '0' && *s <= '9'; s++) {
		if (x > (UINT64_MAX - (uint64_t)(*s - '0')) / 10)
			return -1;
		x = 10 * x + (uint64_t)(*s - '0');
	}
	*v = x;
	return *s == '\0' ? 0 : -1;
}

static double
getreal(const char *s, const char *name, long lineno)
{
	const char *end;
	double v;

	if (parsereal(s, &end, &v) != 0 || *end != '\0')
		errat(name, lineno, "not a number: %s", s);
	return v;
}

static uint64_t
getcount(const char *s, const char *name, long lineno)
{
	uint64_t v;

	if (getu64(s, &v) < 0)
		errat(name, lineno, "not a count: %s", s);
	return v;
}

static void
addxsum(struct xsum *x, char **f, int nf, const char *name, long lineno)
{
	int i;

	for (i = 0; i < nf; i++)
		area_add(x, getreal(f[i], name, lineno));
}

static void
addto128(struct u128 *s, char **f, int sign, const char *name, long lineno)
{
	struct u128 v;

	v.hi = getcount(f[0], name, lineno);
	v.lo = getcount(f[1], name, lineno);
	if (sign > 0) {
		s->lo += v.lo;
		s->hi += v.hi + (s->lo < v.lo);
	} else {
		s->hi -= v.hi + (s->lo < v.lo);
		s->lo -= v.lo;
	}
}

static void
getnodeat(struct claim *c, char **f, int nf, int withclass,
    const char *name, long lineno)
{
	struct nodeat *n = &c->n;
	uint64_t ix, iy, lv = 0;

	if (nf != 4 + withclass || getu64(f[1], &lv) < 0 ||
	    lv > QT_MAXLEVEL || (lv == 0 ? strcmp(f[0], ".") != 0 :
	    strlen(f[0]) != (size_t)lv) ||
	    (withclass && (strchr("NFEP", f[4][0]) == NULL ||
	    f[4][1] != '\0')) ||
	    getu64(f[2], &n->ix) < 0 || getu64(f[3], &n->iy) < 0 ||
	    cell_frompath(f[0], (int)lv, &ix, &iy) < 0 ||
	    ix != n->ix || iy != n->iy)
		errat(name, lineno, "a bad cell: %s %s", f[0],
		    nf > 1 ? f[1] : "");
	n->level = (int)lv;
	memcpy(n->path, f[0], lv);
	n->path[lv] = '\0';
	n->class = withclass ? f[4][0] : 'N';
	c->name = name;
	c->lineno = lineno;
	c->part = mg.partials;
	c->claimed = 0;
}

/* Splits line into fields at spaces, in place; returns their number. */
static int
fields(char *line, char ***f, size_t *cap)
{
	int n = 0;
	char *p = line;

	for (;;) {
		while (*p == ' ')
			p++;
		if (*p == '\0' || *p == '\n')
			break;
		*f = xgrow(*f, cap, (size_t)n + 1, sizeof(**f));
		(*f)[n++] = p;
		while (*p != ' ' && *p != '\0' && *p != '\n')
			p++;
		if (*p == '\0')
			break;
		*p++ = '\0';
	}
	return n;
}

/*
 * The head lines of a partial: the polygon's marks (universe, objects,
 * rings, holes, perimeter), which every partial has, read from the first;
 * the region's sums, which the partial of the tree's root has, read from
 * the first that has them.
 */
static int
headline(const char *line)
{
	static const char *const keys[] = { "universe", "objects", "rings",
	    "holes", "perimeter", "area2", "moment_x", "moment_y", NULL };
	size_t n = strcspn(line, " \n");
	int i;

	for (i = 0; keys[i] != NULL; i++)
		if (strlen(keys[i]) == n && memcmp(line, keys[i], n) == 0)
			return i < 5 ? 1 : 2;
	return 0;
}

static void
mergehead(char **f, int nf, const char *name, long lineno)
{
	const char *k = f[0];

	if (strcmp(k, "universe") == 0 && nf == 4) {
		tree.u.x0 = getreal(f[1], name, lineno);
		tree.u.y0 = getreal(f[2], name, lineno);
		tree.u.size = getreal(f[3], name, lineno);
		tree.haveuniverse = 1;
	} else if (strcmp(k, "objects") == 0 && nf == 2)
		poly.nobjects = (long)getcount(f[1], name, lineno);
	else if (strcmp(k, "rings") == 0 && nf == 2)
		poly.nrings = getcount(f[1], name, lineno);
	else if (strcmp(k, "holes") == 0 && nf == 2)
		poly.nholes = getcount(f[1], name, lineno);
	else if (strcmp(k, "perimeter") == 0 && nf == 3) {
		poly.perim = getreal(f[1], name, lineno);
		poly.perimlow = getreal(f[2], name, lineno);
	} else if (strcmp(k, "area2") == 0)
		addxsum(&poly.region.a2, f + 1, nf - 1, name, lineno);
	else if (strcmp(k, "moment_x") == 0)
		addxsum(&poly.region.mx, f + 1, nf - 1, name, lineno);
	else if (strcmp(k, "moment_y") == 0)
		addxsum(&poly.region.my, f + 1, nf - 1, name, lineno);
	else
		errat(name, lineno, "not a line of qtstats -s: %s", k);
}

/* Lines kept to compare, one buffer each kind. */
struct text {
	char	*b;
	size_t	 len, cap;
};

static void
addtext(struct text *t, const char *line, size_t len)
{
	t->b = xgrow(t->b, &t->cap, t->len + len, 1);
	memcpy(t->b + t->len, line, len);
	t->len += len;
}

static int
sametext(const struct text *a, const struct text *b)
{
	return a->len == b->len && memcmp(a->b, b->b, a->len) == 0;
}

static struct text firstmarks, firstsums;
static int havemarks, havesums;

/* One input of -m: any number of partials, one after another. */
void
mergeinput(const char *path)
{
	const char *name;
	FILE *fp = openin(path, &name);
	char *line = NULL, **f = NULL;
	size_t linecap = 0, fcap = 0, len;
	struct text marks = { NULL, 0, 0 }, psums = { NULL, 0, 0 };
	ssize_t n;
	long lineno = 0, start = 0;
	int nf, in = 0, l, kind = 0;
	struct levelstat *s;

	name = xstrdup(name);	/* messages after the file is closed */
	while ((n = getline(&line, &linecap, fp)) != -1) {
		lineno++;
		len = (size_t)n;
		if (in == 1 && (kind = headline(line)) == 0) {
			/* the head ends: the first's, or the same bytes */
			if (!havemarks) {
				firstmarks = marks;
				marks.b = NULL;
				marks.cap = 0;
				havemarks = 1;
			} else if (!sametext(&marks, &firstmarks))
				errat(name, start, "another polygon: the head "
				    "differs from the first input's");
			if (psums.len > 0 && !havesums) {
				firstsums = psums;
				psums.b = NULL;
				psums.cap = 0;
				havesums = 1;
			} else if (psums.len > 0 &&
			    !sametext(&psums, &firstsums))
				errat(name, start, "another polygon: the "
				    "region's sums differ from the first's");
			in = 2;
		}
		if (in == 1)
			addtext(kind == 1 ? &marks : &psums, line, len);
		if ((nf = fields(line, &f, &fcap)) == 0)
			errat(name, lineno, "an empty line");
		if (in == 0) {
			if (nf != 2 || strcmp(f[0], "qtstats-sums") != 0 ||
			    strcmp(f[1], "1") != 0)
				errat(name, lineno, "not the output of "
				    "qtstats -s: %s", f[0]);
			in = 1;
			start = lineno;
			marks.len = psums.len = 0;
			mg.partials++;
			continue;
		}
		if (in == 1) {
			if (kind == 1 ? !havemarks : !havesums)
				mergehead(f, nf, name, lineno);
			continue;
		}
		if (strcmp(f[0], "end") == 0 && nf == 1) {
			in = 0;
			continue;
		}
		if (strcmp(f[0], "root") == 0) {
			mg.roots = xgrow(mg.roots, &mg.rootcap, mg.nroots + 1,
			    sizeof(*mg.roots));
			getnodeat(&mg.roots[mg.nroots++], f + 1, nf - 1, 1,
			    name, lineno);
		} else if (strcmp(f[0], "dangling") == 0) {
			mg.dangling = xgrow(mg.dangling, &mg.dangcap,
			    mg.ndangling + 1, sizeof(*mg.dangling));
			getnodeat(&mg.dangling[mg.ndangling++], f + 1, nf - 1,
			    0, name, lineno);
		} else if (strcmp(f[0], "level") == 0 && nf == 22) {
			uint64_t lv = getcount(f[1], name, lineno);

			if (lv > QT_MAXLEVEL)
				errat(name, lineno, "level %s is past %d",
				    f[1], QT_MAXLEVEL);
			l = (int)lv;
			s = &tree.lev[l];
			if (l > tree.deepest)
				tree.deepest = l;
			s->nodes += getcount(f[2], name, lineno);
			s->leaves[F] += getcount(f[3], name, lineno);
			s->leaves[E] += getcount(f[4], name, lineno);
			s->leaves[P] += getcount(f[5], name, lineno);
			addto128(&s->nodesx, f + 6, 1, name, lineno);
			addto128(&s->nodesy, f + 8, 1, name, lineno);
			for (l = 0; l < 3; l++) {
				addto128(&s->sx[l], f + 10 + 4 * l, 1, name,
				    lineno);
				addto128(&s->sy[l], f + 12 + 4 * l, 1, name,
				    lineno);
			}
		} else if (strcmp(f[0], "cut") == 0 && nf >= 2) {
			tree.ncut += getcount(f[1], name, lineno);
			addxsum(&tree.cut, f + 2, nf - 2, name, lineno);
		} else
			errat(name, lineno, "not a line of qtstats -s: %s",
			    f[0]);
	}
	if (ferror(fp))
		die(1, "%s: read error", name);
	if (in != 0)
		errat(name, lineno, "truncated: the output of qtstats -s "
		    "that starts at line %ld has no end line", start);
	if (fp != stdin)
		fclose(fp);
	free(line);
	free(f);
	free(marks.b);
	free(psums.b);
}

/* Preorder, then the partial. */
static int
claimcmp(const void *va, const void *vb)
{
	const struct claim *a = va, *b = vb;
	struct cell ca, cb;
	int d;

	ca.level = a->n.level;
	ca.ix = a->n.ix;
	ca.iy = a->n.iy;
	cb.level = b->n.level;
	cb.ix = b->n.ix;
	cb.iy = b->n.iy;
	if ((d = cell_cmp(&ca, &cb)) != 0)
		return d;
	return (a->part > b->part) - (a->part < b->part);
}

static int
samecell(const struct claim *a, const struct claim *b)
{
	return a->n.level == b->n.level && a->n.ix == b->n.ix &&
	    a->n.iy == b->n.iy;
}

/* Whether b is a or inside it. */
static int
within(const struct claim *b, const struct claim *a)
{
	int k = b->n.level - a->n.level;

	return k >= 0 && b->n.ix >> k == a->n.ix && b->n.iy >> k == a->n.iy;
}

/* The first of n claims sorted by claimcmp that is not before c. */
static size_t
lowerbound(const struct claim *v, size_t n, const struct claim *c)
{
	size_t lo = 0, hi = n, mid;
	struct claim k = *c;

	k.part = -1;
	while (lo < hi) {
		mid = lo + (hi - lo) / 2;
		if (claimcmp(&v[mid], &k) < 0)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo;
}

static const char *
claimpath(const struct claim *c)
{
	return c->n.level > 0 ? c->n.path : ".";
}

/* Root r's node, counted by two inputs, taken out of the figures once. */
static void
uncount(const struct claim *r)
{
	struct levelstat *s = &tree.lev[r->n.level];

	s->nodes--;
	add128(&s->nodesx, -(2 * r->n.ix + 1));
	s->nodesx.hi--;
	add128(&s->nodesy, -(2 * r->n.iy + 1));
	s->nodesy.hi--;
}

/*
 * The partials join: a node with no cell below it in its partial (the
 * top of a cut ends in such nodes) has its cells in another partial, of
 * a root at it or below it; a root that is such a node of another
 * partial is counted once, as qtcat writes a node given twice; no two
 * partials have the same root, unless one of them is that node alone.
 */
void
mergejoin(const char *name)
{
	struct claim *r, *d, *e;
	size_t i, j;

	if (mg.partials == 0)
		errat(name, 0, "no output of qtstats -s to merge");
	if (!havesums && poly.nrings > 0 && poly.nobjects == 0)
		errat(name, 0, "no input holds the region's sums, which the "
		    "tree's root carries: merge qtstats -s of the top too");
	if (mg.nroots > 1)
		qsort(mg.roots, mg.nroots, sizeof(*mg.roots), claimcmp);
	if (mg.ndangling > 1)
		qsort(mg.dangling, mg.ndangling, sizeof(*mg.dangling),
		    claimcmp);
	for (i = 0; i < mg.nroots; i++) {
		struct claim *alone = NULL;
		int took = 0;

		r = &mg.roots[i];
		j = lowerbound(mg.dangling, mg.ndangling, r);
		for (; j < mg.ndangling && samecell(d = &mg.dangling[j], r);
		    j++)
			if (d->part == r->part)
				alone = d;	/* a node alone */
			else if (!took && r->n.class == 'N' &&
			    d->claimed == 0) {
				d->claimed = 1;
				uncount(r);
				took = 1;
			}
		if (alone == NULL)
			continue;
		r->claimed = 1;
		/* another input's root too, which took no node for it: once */
		if (!took && ((i > 0 && samecell(&mg.roots[i - 1], r)) ||
		    (i + 1 < mg.nroots && samecell(&mg.roots[i + 1], r)))) {
			alone->claimed = 1;
			uncount(r);
		}
	}
	for (i = 0; i + 1 < mg.nroots; i++)
		if (samecell(r = &mg.roots[i], e = &mg.roots[i + 1]) &&
		    !r->claimed && !e->claimed)
			errat(e->name, e->lineno, "cell %s is the root of two "
			    "inputs: also at %s:%ld", claimpath(r), r->name,
			    r->lineno);
	for (i = 0; i < mg.ndangling; i++) {
		d = &mg.dangling[i];
		j = lowerbound(mg.roots, mg.nroots, d);
		for (; j < mg.nroots && within(&mg.roots[j], d); j++)
			if (mg.roots[j].part != d->part)
				break;
		if (j == mg.nroots || !within(&mg.roots[j], d))
			errat(d->name, d->lineno, "node %s has no cells below "
			    "it in any input: its shard is missing",
			    claimpath(d));
	}
}
