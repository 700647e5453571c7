# Spells some records otherwise than the writers do, all still valid:
# a sign before numbers, a comment, so that readers take their long way.
/^v /s/^v \([0-9]\)/v +\1/
/^leaf /s/^\(leaf [^ ]* [^ ]*\) /\1 +/
/^node /s/^\(node [^ ]* [^ ]* [^ ]* [^ ]* [^ ]*\) /\1 +/
3a\
# a comment
