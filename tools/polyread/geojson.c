/*
 * geojson.c: GeoJSON (RFC 7946): a Polygon, a MultiPolygon, a
 * GeometryCollection of them, a Feature with one of these, or a
 * FeatureCollection of such Features, all of them or those -F chooses.
 *
 * Its own JSON reader, RFC 8259's grammar and nothing more: an object is
 * read whole first, its values checked and skipped, the places of the
 * members GeoJSON gives a meaning kept; then those values are read again
 * from their places.  Other members are ignored.
 */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "polyread.h"

#define MAXDEPTH	64	/* arrays and objects inside one another */

/* A value's place in the input. */
struct jval {
	char	*p;		/* NULL: absent */
	long	 line;
};

enum { TYPE, COORDINATES, GEOMETRIES, GEOMETRY, PROPERTIES, FEATURES,
    NMEMBERS };
static const char *const membername[NMEMBERS] = {
	"type", "coordinates", "geometries", "geometry", "properties",
	"features"
};

/* An object: where it starts, and its members that GeoJSON defines. */
struct jobj {
	struct jval	at;
	struct jval	m[NMEMBERS];
};

/* What -F chooses: a feature by number, or by a property's value. */
static struct {
	const char	*arg;
	long long	 n;		/* 0: by property */
	const char	*key, *val;
	size_t		 keylen, vallen;
	int		 valisnum;
	double		 valnum;
} choice;
static long nfeatures, nchosen;

static void	value(struct src *, int);

/* The input begins an object. */
int
isgeojson(const struct src *s)
{
	return *s->p == '{';
}

static void
ws(struct src *s)
{
	for (;; s->p++)
		if (*s->p == '\n')
			s->line++;
		else if (*s->p != ' ' && *s->p != '\t' && *s->p != '\r')
			return;
}

/* An error at the token the scanner is at, which the message shows. */
static void
bad(struct src *s, const char *what)
{
	size_t n;

	if (*s->p == '\0')
		readerr(s->name, lastline(s), "input ends: %s", what);
	n = strcspn(s->p, " \t\r\n,:[]{}");
	if (n == 0)
		n = 1;
	readerr(s->name, s->line, "%s: %.*s%s", what, n > 32 ? 32 : (int)n,
	    s->p, n > 32 ? "..." : "");
}

static void
punct(struct src *s, int c, const char *what)
{
	ws(s);
	if (*s->p != c)
		bad(s, what);
	s->p++;
}

static void
deeper(struct src *s, int depth)
{
	if (depth > MAXDEPTH)
		readerr(s->name, s->line, "JSON nested deeper than %d levels",
		    MAXDEPTH);
}

/* Starts an array: whether it has elements. */
static int
first(struct src *s, int depth, const char *what)
{
	deeper(s, depth);
	punct(s, '[', what);
	ws(s);
	if (*s->p == ']') {
		s->p++;
		return 0;
	}
	return 1;
}

/* After an element: whether another follows. */
static int
next(struct src *s)
{
	ws(s);
	if (*s->p == ',') {
		s->p++;
		return 1;
	}
	if (*s->p != ']')
		bad(s, "expected ',' or ']'");
	s->p++;
	return 0;
}

static unsigned
hex4(struct src *s, const char *p)
{
	unsigned v = 0;
	int i;

	for (i = 0; i < 4; i++) {
		int c = (unsigned char)p[i];

		if (!isxdigit(c)) {
			s->p = (char *)p - 2;
			bad(s, "bad \\u escape in a string");
		}
		v = v * 16 + (isdigit(c) ? c - '0' : tolower(c) - 'a' + 10);
	}
	return v;
}

/* The bytes of a UTF-8 sequence starting at p, or 0 when it is not one. */
static int
utf8len(const unsigned char *p)
{
	int n, i;

	if (p[0] < 0x80)
		return 1;
	if (p[0] >= 0xc2 && p[0] <= 0xdf)
		n = 2;
	else if (p[0] >= 0xe0 && p[0] <= 0xef)
		n = 3;
	else if (p[0] >= 0xf0 && p[0] <= 0xf4)
		n = 4;
	else
		return 0;
	for (i = 1; i < n; i++)
		if ((p[i] & 0xc0) != 0x80)
			return 0;
	/* overlong forms, surrogates, beyond U+10FFFF */
	if ((p[0] == 0xe0 && p[1] < 0xa0) || (p[0] == 0xed && p[1] > 0x9f) ||
	    (p[0] == 0xf0 && p[1] < 0x90) || (p[0] == 0xf4 && p[1] > 0x8f))
		return 0;
	return n;
}

static void
put(char *out, size_t cap, size_t *len, const char *b, size_t n)
{
	if (out != NULL && *len + n <= cap)
		memcpy(out + *len, b, n);
	*len += n;
}

/*
 * A string, checked and skipped; decoded into out when out is not NULL,
 * as far as cap bytes go.  Returns its decoded length.
 */
static size_t
jstring(struct src *s, char *out, size_t cap)
{
	const char *p;
	size_t len = 0;

	ws(s);
	if (*s->p != '"')
		bad(s, "expected a string");
	for (p = s->p + 1; *p != '"'; ) {
		char b[4];
		unsigned u, lo = 0;
		int n;

		if (*p == '\0') {
			s->p = (char *)p;
			bad(s, "expected '\"' to end a string");
		}
		if ((unsigned char)*p < 0x20) {
			s->p = (char *)p;
			readerr(s->name, s->line, "control character in a "
			    "string");
		}
		if (*p != '\\') {
			if ((n = utf8len((const unsigned char *)p)) == 0) {
				s->p = (char *)p;
				readerr(s->name, s->line, "string is not "
				    "UTF-8");
			}
			put(out, cap, &len, p, n);
			p += n;
			continue;
		}
		switch (p[1]) {
		case '"': case '\\': case '/':
			b[0] = p[1];
			break;
		case 'b': b[0] = '\b'; break;
		case 'f': b[0] = '\f'; break;
		case 'n': b[0] = '\n'; break;
		case 'r': b[0] = '\r'; break;
		case 't': b[0] = '\t'; break;
		case 'u':
			u = hex4(s, p + 2);
			p += 6;
			if (u >= 0xdc00 && u <= 0xdfff) {
				s->p = (char *)p - 6;
				bad(s, "lone surrogate in a string");
			}
			if (u >= 0xd800 && u <= 0xdbff) {
				if (p[0] != '\\' || p[1] != 'u' ||
				    (lo = hex4(s, p + 2)) < 0xdc00 ||
				    lo > 0xdfff) {
					s->p = (char *)p - 6;
					bad(s, "lone surrogate in a string");
				}
				u = 0x10000 + ((u - 0xd800) << 10) +
				    (lo - 0xdc00);
				p += 6;
			}
			if (u < 0x80) {
				b[0] = u;
				n = 1;
			} else if (u < 0x800) {
				b[0] = 0xc0 | u >> 6;
				b[1] = 0x80 | (u & 0x3f);
				n = 2;
			} else if (u < 0x10000) {
				b[0] = 0xe0 | u >> 12;
				b[1] = 0x80 | (u >> 6 & 0x3f);
				b[2] = 0x80 | (u & 0x3f);
				n = 3;
			} else {
				b[0] = 0xf0 | u >> 18;
				b[1] = 0x80 | (u >> 12 & 0x3f);
				b[2] = 0x80 | (u >> 6 & 0x3f);
				b[3] = 0x80 | (u & 0x3f);
				n = 4;
			}
			put(out, cap, &len, b, n);
			continue;
		default:
			s->p = (char *)p;
			bad(s, "bad escape in a string");
		}
		put(out, cap, &len, b, 1);
		p += 2;
	}
	s->p = (char *)p + 1;
	return len;
}

/* A number in JSON's syntax: no '+', no leading zeros, no hex, NaN or Inf. */
static const char *
numberend(const char *p)
{
	if (*p == '-')
		p++;
	if (*p == '0')
		p++;
	else if (*p >= '1' && *p <= '9')
		p += strspn(p, "0123456789");
	else
		return NULL;
	if (*p == '.') {
		if (!isdigit((unsigned char)p[1]))
			return NULL;
		p += 1 + strspn(p + 1, "0123456789");
	}
	if (*p == 'e' || *p == 'E') {
		p++;
		if (*p == '+' || *p == '-')
			p++;
		if (!isdigit((unsigned char)*p))
			return NULL;
		p += strspn(p, "0123456789");
	}
	/* what may follow a number: "01" and "1x" are not two tokens */
	if (*p != '\0' && strchr(" \t\r\n,]}", *p) == NULL)
		return NULL;
	return p;
}

static double
jnumber(struct src *s)
{
	const char *end;
	double v;

	ws(s);
	if ((end = numberend(s->p)) == NULL)
		bad(s, "not a JSON number");
	if (parsereal(s->p, &end, &v) == -2)
		bad(s, "number out of range");
	s->p = (char *)end;
	return v;
}

static void
literal(struct src *s)
{
	static const char *const words[] = { "true", "false", "null" };
	size_t i, n;

	for (i = 0; i < 3; i++) {
		n = strlen(words[i]);
		if (strncmp(s->p, words[i], n) == 0 &&
		    !isalnum((unsigned char)s->p[n])) {
			s->p += n;
			return;
		}
	}
	bad(s, "expected a JSON value");
}

/*
 * An object, checked and skipped; when o is not NULL, the places of the
 * members GeoJSON defines go there.
 */
static void
object(struct src *s, struct jobj *o, int depth)
{
	deeper(s, depth);
	ws(s);
	if (o != NULL) {
		memset(o, 0, sizeof(*o));
		o->at.p = s->p;
		o->at.line = s->line;
	}
	punct(s, '{', "expected an object");
	ws(s);
	if (*s->p == '}') {
		s->p++;
		return;
	}
	do {
		char key[16];
		size_t len;
		int i = NMEMBERS;

		ws(s);
		len = jstring(s, key, sizeof(key));
		if (o != NULL)
			for (i = 0; i < NMEMBERS; i++)
				if (len == strlen(membername[i]) &&
				    memcmp(key, membername[i], len) == 0)
					break;
		punct(s, ':', "expected ':'");
		ws(s);
		if (i < NMEMBERS) {
			if (o->m[i].p != NULL)
				readerr(s->name, s->line, "a second \"%s\" "
				    "member in one object", membername[i]);
			o->m[i].p = s->p;
			o->m[i].line = s->line;
		}
		value(s, depth + 1);
		ws(s);
	} while (*s->p == ',' && s->p++);
	if (*s->p != '}')
		bad(s, "expected ',' or '}'");
	s->p++;
}

/* Any value, checked and skipped. */
static void
value(struct src *s, int depth)
{
	ws(s);
	switch (*s->p) {
	case '{':
		object(s, NULL, depth);
		break;
	case '[':
		if (first(s, depth, "expected '['"))
			do
				value(s, depth + 1);
			while (next(s));
		break;
	case '"':
		jstring(s, NULL, 0);
		break;
	case '-': case '0': case '1': case '2': case '3': case '4':
	case '5': case '6': case '7': case '8': case '9':
		jnumber(s);
		break;
	default:
		literal(s);
	}
}

static void
go(struct src *s, const struct jval *v)
{
	s->p = v->p;
	s->line = v->line;
}

/* The value of the object's type member, which must be a string. */
static void
type(struct src *s, const struct jobj *o, char *buf, size_t cap)
{
	size_t len;

	if (o->m[TYPE].p == NULL)
		readerr(s->name, o->at.line, "GeoJSON object without a "
		    "\"type\" member");
	go(s, &o->m[TYPE]);
	len = jstring(s, buf, cap - 1);
	buf[len < cap - 1 ? len : cap - 1] = '\0';
	if (strlen(buf) != len)
		buf[0] = '\0';		/* no type: too long, or a NUL */
	go(s, &o->m[TYPE]);
}

/* RFC 7946, 7.1: members that would make an object two kinds at once. */
static void
forbid(struct src *s, const struct jobj *o, const char *kind, int m)
{
	if (o->m[m].p != NULL)
		readerr(s->name, o->m[m].line, "a %s must not have a \"%s\" "
		    "member", kind, membername[m]);
}

/*
 * A ring: at least 4 positions, the last the first again, each [x, y] or
 * [x, y, z]; the altitude z is dropped.
 */
static void
ring(struct src *s, struct input *in, int role, int depth)
{
	struct inring *r;
	long line;

	ws(s);
	r = newring(in, s->name, s->line, role, in->npolys);
	line = s->line;
	if (first(s, depth, "expected a ring, an array of positions"))
		do {
			double x, y;

			ws(s);
			line = s->line;
			if (!first(s, depth + 1, "expected a position, [x, y]"))
				readerr(s->name, line, "empty position");
			x = jnumber(s);
			if (!next(s))
				readerr(s->name, line, "position with one "
				    "number");
			y = jnumber(s);
			if (next(s)) {
				jnumber(s);
				if (next(s))
					readerr(s->name, line, "position with "
					    "more than 3 numbers");
			}
			addvertex(in, r, x, y, line);
		} while (next(s));
	if (r->n < 4)
		readerr(s->name, line, "ring has fewer than 4 positions");
	if (r->v[0].x != r->v[r->n - 1].x || r->v[0].y != r->v[r->n - 1].y)
		readerr(s->name, line, "ring is not closed (the last position "
		    "must repeat the first)");
}

/* A Polygon's coordinates: its shell, then its holes. */
static void
polygon(struct src *s, struct input *in, int depth)
{
	size_t before = in->nrings;
	int k = 0;

	if (first(s, depth, "expected a polygon, an array of rings"))
		do
			ring(s, in, k++ == 0 ? OUTER : HOLE, depth + 1);
		while (next(s));
	if (in->nrings > before)
		in->npolys++;
}

static void
geometry(struct src *s, struct input *in, const struct jobj *o, int depth)
{
	char t[24];

	type(s, o, t, sizeof(t));
	forbid(s, o, "geometry", GEOMETRY);
	forbid(s, o, "geometry", PROPERTIES);
	forbid(s, o, "geometry", FEATURES);
	if (strcmp(t, "GeometryCollection") == 0) {
		struct jobj g;

		if (o->m[GEOMETRIES].p == NULL)
			readerr(s->name, o->at.line, "a GeometryCollection "
			    "without a \"geometries\" member");
		go(s, &o->m[GEOMETRIES]);
		if (first(s, depth, "expected an array of geometries"))
			do {
				struct jval end;

				object(s, &g, depth + 1);
				end.p = s->p;
				end.line = s->line;
				geometry(s, in, &g, depth + 1);
				go(s, &end);
			} while (next(s));
		return;
	}
	if (strcmp(t, "Polygon") != 0 && strcmp(t, "MultiPolygon") != 0) {
		if (strcmp(t, "Point") == 0 || strcmp(t, "MultiPoint") == 0 ||
		    strcmp(t, "LineString") == 0 ||
		    strcmp(t, "MultiLineString") == 0)
			readerr(s->name, s->line, "a %s bounds no region: only "
			    "Polygon and MultiPolygon geometries are read", t);
		bad(s, "not a GeoJSON geometry type");
	}
	if (o->m[COORDINATES].p == NULL)
		readerr(s->name, o->at.line, "a %s without a \"coordinates\" "
		    "member", t);
	go(s, &o->m[COORDINATES]);
	if (strcmp(t, "Polygon") == 0)
		polygon(s, in, depth);
	else if (first(s, depth, "expected an array of polygons"))
		do
			polygon(s, in, depth + 1);
		while (next(s));
}

/* Whether the feature's properties hold the one -F names, with its value. */
static int
chosenby(struct src *s, const struct jobj *f, int depth)
{
	int match = 0;

	if (f->m[PROPERTIES].p == NULL)
		return 0;
	go(s, &f->m[PROPERTIES]);
	if (*s->p != '{')
		return 0;
	s->p++;
	ws(s);
	if (*s->p == '}')
		return 0;
	do {
		char *key = xmalloc(choice.keylen + 1);
		size_t len;
		int this;

		len = jstring(s, key, choice.keylen);
		this = len == choice.keylen &&
		    memcmp(key, choice.key, len) == 0;
		free(key);
		punct(s, ':', "expected ':'");
		ws(s);
		if (this && *s->p == '"') {
			char *val = xmalloc(choice.vallen + 1);

			len = jstring(s, val, choice.vallen);
			match = len == choice.vallen &&
			    memcmp(val, choice.val, len) == 0;
			free(val);
		} else if (this && (*s->p == '-' || isdigit((unsigned char)
		    *s->p))) {
			double v = jnumber(s);

			match = choice.valisnum && v == choice.valnum;
		} else if (this && isalpha((unsigned char)*s->p)) {
			match = strncmp(s->p, choice.val, choice.vallen) == 0 &&
			    !isalnum((unsigned char)s->p[choice.vallen]);
			literal(s);
		} else
			value(s, depth + 1);
		if (match)
			return 1;
		ws(s);
	} while (*s->p == ',' && s->p++);
	return 0;
}

static void
feature(struct src *s, struct input *in, const struct jobj *f, int depth)
{
	char t[24];
	struct jobj g;

	type(s, f, t, sizeof(t));
	if (strcmp(t, "Feature") != 0)
		bad(s, "a feature's type must be \"Feature\"");
	forbid(s, f, "Feature", COORDINATES);
	forbid(s, f, "Feature", GEOMETRIES);
	forbid(s, f, "Feature", FEATURES);
	nfeatures++;
	if (choice.arg != NULL && (choice.n > 0 ? nfeatures != choice.n :
	    !chosenby(s, f, depth)))
		return;
	nchosen++;
	if (f->m[GEOMETRY].p == NULL)
		readerr(s->name, f->at.line, "a Feature without a "
		    "\"geometry\" member");
	go(s, &f->m[GEOMETRY]);
	if (strncmp(s->p, "null", 4) == 0)
		return;		/* a feature without a place */
	object(s, &g, depth + 1);
	geometry(s, in, &g, depth + 1);
}

void
parsegeojson(struct src *s, struct input *in)
{
	struct jobj o, f;
	struct jval end;
	char t[24];

	nfeatures = nchosen = 0;
	ws(s);
	if (*s->p != '{')
		bad(s, "expected a GeoJSON object");
	object(s, &o, 1);
	end.p = s->p;
	end.line = s->line;
	ws(s);
	if (*s->p != '\0')
		bad(s, "data after the GeoJSON object");
	type(s, &o, t, sizeof(t));
	if (strcmp(t, "FeatureCollection") == 0) {
		forbid(s, &o, "FeatureCollection", COORDINATES);
		forbid(s, &o, "FeatureCollection", GEOMETRIES);
		forbid(s, &o, "FeatureCollection", GEOMETRY);
		forbid(s, &o, "FeatureCollection", PROPERTIES);
		if (o.m[FEATURES].p == NULL)
			readerr(s->name, o.at.line, "a FeatureCollection "
			    "without a \"features\" member");
		go(s, &o.m[FEATURES]);
		if (first(s, 2, "expected an array of features"))
			do {
				object(s, &f, 3);
				end.p = s->p;
				end.line = s->line;
				feature(s, in, &f, 3);
				go(s, &end);
			} while (next(s));
	} else if (strcmp(t, "Feature") == 0)
		feature(s, in, &o, 1);
	else if (choice.arg != NULL)
		readerr(s->name, o.at.line, "-F chooses among features, and "
		    "this input is a bare %s", t);
	else
		geometry(s, in, &o, 1);
	if (choice.arg != NULL && nchosen == 0)
		readerr(s->name, 0, "-F %s: no such feature among the %ld "
		    "in the input", choice.arg, nfeatures);
}

/* -F: a feature's number, counted from 1, or name=value. */
void
choosefeature(const char *arg)
{
	const char *eq = strchr(arg, '='), *end;

	choice.arg = arg;
	if (eq == NULL) {
		if (parselong(arg, &end, &choice.n) < 0 || *end != '\0' ||
		    choice.n < 1)
			die(2, "-F: expected a feature number from 1, or "
			    "name=value: %s", arg);
		return;
	}
	if (eq == arg)
		die(2, "-F: expected a property name before '=': %s", arg);
	choice.n = 0;
	choice.key = arg;
	choice.keylen = eq - arg;
	choice.val = eq + 1;
	choice.vallen = strlen(eq + 1);
	choice.valisnum = parsereal(choice.val, &end, &choice.valnum) == 0 &&
	    *end == '\0' && choice.vallen > 0;
}
