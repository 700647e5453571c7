/*
 * obj.c: Wavefront OBJ: v x y z [w] a vertex, f a b c ... a polygon of
 * vertices counted from 1 (negative: back from the last read), each maybe
 * with /texture/normal numbers, which are ignored, as are the statements
 * that do not shape the surface (vn, vt, vp, o, g, s, usemtl, mtllib).
 */
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "polyread.h"

static const char *const ignored[] = { "vn", "vt", "vp", "o", "g", "s",
    "usemtl", "mtllib" };

static int
statement(const char *p, size_t n)
{
	size_t i;

	if (n == 1 && (*p == 'v' || *p == 'f'))
		return *p;
	for (i = 0; i < sizeof(ignored) / sizeof(ignored[0]); i++)
		if (n == strlen(ignored[i]) && strncmp(p, ignored[i], n) == 0)
			return 'i';
	return 0;
}

/* The first word of data is an OBJ statement and more words follow. */
int
isobj(const struct src *s)
{
	const char *f[2];
	size_t len[2];

	return linefields(s->p, f, len, 2) >= 2 && statement(f[0], len[0]);
}

void
parseobj(struct src *s, struct input *in)
{
	size_t base = in->solid != NULL ? in->solid->nv : 0, *v = NULL, cap = 0;
	size_t nv = 0, n;
	const char *f[1];
	size_t len[1];

	while (skipspace(s)) {
		long line = s->line;
		int k = 0;

		if (linefields(s->p, f, len, 1) < 1 || (k = statement(f[0],
		    len[0])) == 0)
			badtoken(s, "not an OBJ statement polyread reads (v, f, "
			    "or one it ignores)");
		s->p += len[0];
		if (k == 'v') {
			double x = number(s, "x"), y = number(s, "y");
			double z = number(s, "z");

			if (s->line != line)
				readerr(s->name, line, "v record of fewer "
				    "than 3 coordinates");
			addpoint3(in, s->name, line, x, y, z);
			nv++;
		} else if (k == 'f') {
			for (n = 0; skipspace(s) && s->line == line; n++) {
				char *end;
				long long i = strtoll(s->p, &end, 10);

				if (end == s->p || (*end != '/' && *end != ' ' &&
				    *end != '\t' && *end != '\r' && *end != '\n' &&
				    *end != '\0'))
					badtoken(s, "not a vertex number");
				if (i < 0)
					i += (long long)nv + 1;
				if (i < 1 || i > (long long)nv)
					readerr(s->name, line, "vertex %.*s "
					    "is not one of the %zu read so far",
					    (int)(end - s->p), s->p, nv);
				v = xgrow(v, &cap, n + 1, sizeof(*v));
				v[n] = base + (size_t)i - 1;
				while (*s->p != ' ' && *s->p != '\t' &&
				    *s->p != '\n' && *s->p != '\r' && *s->p != '\0')
					s->p++;
			}
			addpoly3(in, s->name, line, v, n);
			continue;
		}
		restofline(s);
	}
	free(v);
}
