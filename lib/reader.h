/*
 * reader.h: the qtree(5) reader's state, shared by read.c (the stream,
 * cells, mesh records) and readhead.c (the records of a stream's head:
 * universe, level, rings, objects, op).
 */
enum { BEFORE_HEADER, IN_BODY, AFTER_END };

#define NFIELD	64	/* fields of a record, an elem's at most */

struct buf {
	char	*s;
	size_t	 len, cap;
};

struct qtreader {
	FILE		*fp;
	const char	*name;
	int		 flags;
	long		 lineno;
	char		*buf;
	size_t		 cap, pos, end;	/* unread input: buf[pos..end-1] */
	int		 eof;
	int		 nonewline;	/* the last line read had none */
	int		 state;
	unsigned long long count;	/* records, for the end record */
	char		*field[NFIELD];
	int		 nfield;
	int		 haveuniverse, havelevel, havecells;
	int		 solid;		/* a 3D stream, for read3.c */
	int		 deepest;	/* the deepest cell's level, -1 before one */
	struct universe	 u;
	int		 ulevels;	/* the universe's deepest level */
	int		 level;		/* the level record's */
	struct celltext	*text;	/* shared with the writer */
	char		 tail[192];	/* a cell's fields after its level */
	/* the last cell: its path, NUL-terminated, and its prefixes' cells */
	char		 path[QT_MAXLEVEL + 1];
	int		 pathlen;
	int		 lastleaf;
	uint64_t	 pathix[QT_MAXLEVEL + 1], pathiy[QT_MAXLEVEL + 1];
	/* the ring being read: its vertices and its text */
	long		 nrings;
	struct ring	 ring;
	size_t		 ringcap, vleft;
	long		 ringline;
	int		 lasta;		/* the last ring record was an a */
	struct buf	 ringtext;
	/* a combined stream's objects so far, and its op record */
	long		 nobjects;
	int		 haveop;
	int		 opterm[NFIELD];
	/* the mesh read so far */
	unsigned long long nvertex, nelem;
	unsigned long long elemv[NFIELD];
	char		*type;
	size_t		 typecap;
};

/* read.c: a record's fields, checked; a defect ends the program */
double	 read_realfield(struct qtreader *, const char *, const char *);
long long read_intfield(struct qtreader *, const char *, const char *,
	    long long, long long);
void	 read_nfields(struct qtreader *, int, int);

/* readhead.c: readhead_v returns 1 when its record completes the ring */
void	 readhead_universe(struct qtreader *, struct qtrec *);
void	 readhead_level(struct qtreader *, struct qtrec *);
void	 readhead_ring(struct qtreader *);
int	 readhead_v(struct qtreader *, int);
void	 readhead_object(struct qtreader *, struct qtrec *);
void	 readhead_op(struct qtreader *, struct qtrec *);
