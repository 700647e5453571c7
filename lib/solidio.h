/*
 * solidio.h: what the 2D reader and writer lend the 3D ones (read3.c,
 * write3.c), so that a 3D stream's lines are read, counted and written as
 * a 2D stream's are.
 */

/* read.c: lines and fields read and checked as 2D ones. */
char	*qt_rawline(struct qtreader *, size_t *);
char	*qt_unread(struct qtreader *, const char **);
void	 qt_skipline(struct qtreader *, size_t);
long	 qt_lineno(const struct qtreader *);
int	 qt_flags(const struct qtreader *);
double	 qt_realfield(struct qtreader *, const char *, const char *);
long long qt_intfield(struct qtreader *, const char *, const char *,
	    long long, long long);

/*
 * write.c: n bytes holding k records, newlines included; or a record
 * formatted in place, in the room for n bytes qt_room gives, taken up to
 * its end, newline included, by qt_recorded.
 */
void	 qt_putrecords(const char *, size_t, unsigned long long);
char	*qt_room(size_t);
void	 qt_recorded(const char *);

/*
 * read.c's fast way, which read3.c takes too: fields as the writers spell
 * them.  A level, then a space.
 */
static inline const char *
fastlevel(const char *p, int level)
{
	if (level >= 10 && *p++ != '0' + level / 10)
		return NULL;
	if (p[0] != '0' + level % 10 || p[1] != ' ')
		return NULL;
	return p + 2;
}

/*
 * An element number as the writers spell it; returns where it stops, the
 * line's end when the line is well-formed.
 */
static inline const char *
fastid(const char *p, unsigned long long *id)
{
	unsigned long long v = 0;
	const char *start = p;
	unsigned d;

	if (*p == '0')
		return NULL;
	for (; (d = (unsigned char)*p - '0') <= 9; p++) {
		if (p - start == 18)
			return NULL;
		v = v * 10 + d;
	}
	if (p == start)
		return NULL;
	*id = v;
	return p;
}
