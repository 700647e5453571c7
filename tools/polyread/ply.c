/*
 * ply.c: PLY, ASCII or binary little-endian: a header of elements and
 * their properties up to end_header, then each element's records.  The
 * vertex element's x, y and z are the points, the face element's list
 * vertex_indices (or vertex_index) the polygons, counted from 0; other
 * elements and properties are read past.  Counts are trusted for nothing:
 * the records are read as they come, and an input that ends early says so.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "polyread.h"

enum { MAXPROP = 64, MAXELEM = 16 };

struct prop {
	int	type, ltype;	/* sizes' codes below; ltype > 0 for a list */
	int	role;		/* 'x', 'y', 'z', 'i' (indices), 0 */
};

struct elem {
	char		 name[32];
	long long	 count;
	struct prop	 prop[MAXPROP];
	int		 nprop;
};

static const struct {
	const char	*name;
	int		 size;
	int		 isfloat, issigned;
} types[] = {
	{ "char", 1, 0, 1 }, { "uchar", 1, 0, 0 }, { "short", 2, 0, 1 },
	{ "ushort", 2, 0, 0 }, { "int", 4, 0, 1 }, { "uint", 4, 0, 0 },
	{ "float", 4, 1, 1 }, { "double", 8, 1, 1 }, { "int8", 1, 0, 1 },
	{ "uint8", 1, 0, 0 }, { "int16", 2, 0, 1 }, { "uint16", 2, 0, 0 },
	{ "int32", 4, 0, 1 }, { "uint32", 4, 0, 0 }, { "float32", 4, 1, 1 },
	{ "float64", 8, 1, 1 },
};
#define NTYPES	(int)(sizeof(types) / sizeof(types[0]))

int
isply(const struct src *s)
{
	return strncmp(s->buf, "ply\n", 4) == 0 ||
	    strncmp(s->buf, "ply\r\n", 5) == 0;
}

static int
typenamed(struct src *s, const char *p, size_t n, long line)
{
	int i;

	for (i = 0; i < NTYPES; i++)
		if (strlen(types[i].name) == n &&
		    strncmp(types[i].name, p, n) == 0)
			return i;
	readerr(s->name, line, "unknown PLY type %.*s", (int)n, p);
	return -1;
}

struct plyread {
	struct src	*s;
	int		 binary;
	const unsigned char *p, *end;	/* binary data */
	long long	 elem, item;	/* for messages */
	const char	*ename;
};

/* One value of a type, from the text or the bytes. */
static double
value(struct plyread *r, int type)
{
	const unsigned char *p = r->p;
	int n = types[type].size;
	uint64_t u = 0;
	int i;

	if (!r->binary) {
		if (!skipspace(r->s))
			readerr(r->s->name, lastline(r->s), "input ends in "
			    "%s %lld of %lld", r->ename, r->item, r->elem);
		return number(r->s, "a PLY value");
	}
	if (r->end - p < n)
		readerr(r->s->name, 0, "input ends in %s %lld of %lld (binary "
		    "PLY: the header's counts are more than the file holds)",
		    r->ename, r->item, r->elem);
	for (i = n - 1; i >= 0; i--)
		u = u << 8 | p[i];
	r->p += n;
	if (types[type].isfloat) {
		if (n == 4) {
			uint32_t w = (uint32_t)u;
			float f;

			memcpy(&f, &w, 4);
			return f;
		} else {
			double d;

			memcpy(&d, &u, 8);
			return d;
		}
	}
	if (types[type].issigned && n < 8 && (u >> (8 * n - 1)) & 1)
		return (double)(int64_t)(u | ~(((uint64_t)1 << 8 * n) - 1));
	return (double)u;
}

static void
header(struct src *s, struct elem *e, int *ne, int *binary)
{
	const char *f[8];
	size_t len[8];
	int n;

	*ne = 0;
	*binary = -1;
	restofline(s);		/* ply */
	for (;;) {
		long line;

		if (*s->p == '\n') {
			s->p++;
			s->line++;
		}
		line = s->line;
		if (*s->p == '\0')
			readerr(s->name, line, "PLY header without end_header");
		n = linefields(s->p, f, len, 8);
		if (n == 0) {
			restofline(s);
			continue;
		}
#define IS(i, w)	(len[i] == strlen(w) && strncmp(f[i], w, len[i]) == 0)
		if (IS(0, "end_header")) {
			restofline(s);
			if (*s->p == '\n') {
				s->p++;
				s->line++;
			}
			break;
		}
		if (IS(0, "comment") || IS(0, "obj_info"))
			;
		else if (IS(0, "format") && n == 3) {
			if (IS(1, "ascii"))
				*binary = 0;
			else if (IS(1, "binary_little_endian"))
				*binary = 1;
			else
				readerr(s->name, line, "PLY format %.*s is not "
				    "read (ascii and binary_little_endian are)",
				    (int)len[1], f[1]);
		} else if (IS(0, "element") && n == 3) {
			char *end;
			struct elem *el;

			if (*ne == MAXELEM)
				readerr(s->name, line, "more than %d PLY "
				    "elements", MAXELEM);
			el = &e[(*ne)++];
			memset(el, 0, sizeof(*el));
			snprintf(el->name, sizeof(el->name), "%.*s",
			    (int)len[1], f[1]);
			el->count = strtoll(f[2], &end, 10);
			if (end != f[2] + len[2] || el->count < 0)
				readerr(s->name, line, "PLY element count is "
				    "not a count: %.*s", (int)len[2], f[2]);
		} else if (IS(0, "property") && *ne > 0 && (n == 3 || (n == 5 &&
		    IS(1, "list")))) {
			struct elem *el = &e[*ne - 1];
			struct prop *pr;
			int k = n - 1;

			if (el->nprop == MAXPROP)
				readerr(s->name, line, "more than %d PLY "
				    "properties", MAXPROP);
			pr = &el->prop[el->nprop++];
			pr->ltype = n == 5 ? typenamed(s, f[2], len[2], line) + 1 :
			    0;
			pr->type = typenamed(s, f[k - 1], len[k - 1], line);
			pr->role = 0;
			if (strcmp(el->name, "vertex") == 0 && n == 3 &&
			    len[k] == 1 && strchr("xyz", *f[k]) != NULL)
				pr->role = *f[k];
			if (strcmp(el->name, "face") == 0 && n == 5 &&
			    (IS(k, "vertex_indices") || IS(k, "vertex_index")))
				pr->role = 'i';
		} else
			readerr(s->name, line, "not a PLY header line polyread "
			    "reads: %.*s", (int)len[0], f[0]);
#undef IS
		restofline(s);
	}
	if (*binary < 0)
		readerr(s->name, s->line, "PLY header without a format line");
}

void
parseply(struct src *s, struct input *in)
{
	struct elem e[MAXELEM];
	struct plyread r;
	size_t base = in->solid != NULL ? in->solid->nv : 0, *v = NULL, cap = 0;
	long long nv = -1;
	int ne, i, k;

	s->p = s->buf;
	if (!isply(s))
		readerr(s->name, 1, "not PLY: the first line is not ply");
	header(s, e, &ne, &r.binary);
	r.s = s;
	r.p = (const unsigned char *)s->p;
	r.end = (const unsigned char *)s->buf + s->len;
	for (i = 0; i < ne; i++) {
		long long j;

		r.ename = e[i].name;
		r.elem = e[i].count;
		for (j = 0; j < e[i].count; j++) {
			double c[3] = { 0, 0, 0 };
			long line = s->line;
			size_t n = 0;

			r.item = j + 1;
			if (!r.binary && !skipspace(s))
				readerr(s->name, lastline(s), "input ends after "
				    "%lld of %lld %s records", j, e[i].count,
				    e[i].name);
			line = r.binary ? 0 : s->line;
			for (k = 0; k < e[i].nprop; k++) {
				const struct prop *pr = &e[i].prop[k];
				double m;
				long long q;

				if (pr->ltype == 0) {
					double x = value(&r, pr->type);

					if (pr->role)
						c[pr->role - 'x'] = x;
					continue;
				}
				m = value(&r, pr->ltype - 1);
				if (m < 0 || m > 1 << 20 || m != (long long)m)
					readerr(s->name, line, "PLY list length "
					    "is not a count: %g", m);
				for (q = 0; q < (long long)m; q++) {
					double x = value(&r, pr->type);

					if (pr->role != 'i')
						continue;
					if (x < 0 || x >= nv || x != (long long)x)
						readerr(s->name, line, "face %lld: "
						    "vertex %g is not one of the "
						    "%lld vertices", j + 1, x, nv);
					v = xgrow(v, &cap, n + 1, sizeof(*v));
					v[n++] = base + (size_t)x;
				}
			}
			if (strcmp(e[i].name, "vertex") == 0)
				addpoint3(in, s->name, line, c[0], c[1], c[2]);
			else if (strcmp(e[i].name, "face") == 0)
				addpoly3(in, s->name, line, v, n);
		}
		if (strcmp(e[i].name, "vertex") == 0)
			nv = e[i].count;
	}
	if (r.binary ? r.p != r.end : skipspace(s))
		readerr(s->name, r.binary ? 0 : s->line, "data after the last "
		    "PLY element");
	free(v);
}
