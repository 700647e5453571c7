/*
 * qtcat.h: what qtcat.c (heads, the merge) and qtcatcopy.c (shard files
 * copied whole) share.
 */

/* A shard to copy whole: its cells' bytes, its first and last cells. */
struct block {
	int		 fd;
	off_t		 from, to;	/* the cells' lines, first to last */
	size_t		 firstlen;	/* the first cell's line */
	unsigned long long ncells;	/* as its end record counts them */
	char		 firstpath[QT_MAXLEVEL + 1], lastpath[QT_MAXLEVEL + 1];
	struct cell	 last;
};

struct input {
	const char	*name;
	const char	*path;	/* the operand */
	struct qtreader	*r;
	struct qtrec	 rec;	/* the current cell */
	int		 dim;	/* 2 or 3, 0 before a record */
	struct qt3reader *s;	/* a 3D stream's reader, on r */
	struct qt3rec	 rec3;	/* and its record, given in rec */
	int		 done;
	long		 lineno;	/* of the cell before it */
	struct block	*b;	/* not NULL: copied whole */
};

/* The first head as its bytes, the qtree line first, and its records. */
extern char *headtext;
extern size_t headlen;
extern unsigned long long headrecs;
extern long headlines;

/* The inputs' dimension, 2 or 3 (0 before a record); a path's last digit. */
extern int dim;
extern char lastdigit;

#define CHUNK	(1 << 20)	/* a read of a shard copied whole */
#define WINDOW	(1 << 28)	/* a mapping of a shard copied whole */
extern char *chunk;

/* qtcatcopy.c */
ssize_t	 readat(int, char *, size_t, off_t);
int	 probe(struct input *, const char *);
unsigned long long newlines(const char *, size_t);
size_t	 copyspan(struct input *, off_t, unsigned long long *);
