/*
 * solidio.h: what the 2D reader and writer lend the 3D ones (read3.c,
 * write3.c), so that a 3D stream's lines are read, counted and written as
 * a 2D stream's are.
 */

/* read.c: lines and fields read and checked as 2D ones. */
char	*qt_rawline(struct qtreader *, size_t *);
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
