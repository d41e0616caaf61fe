# The library's remedies (meromorph_remedy codes in meromorph.h) in a Blender user's words: this
# operator's options and Blender's menus.
#
# In:  a remedy code, or a message with its codes, or a map's advice as (cause, code) pairs.
# Out: the words, "message; remedy", "cause: remedy; cause: remedy".

WORDS = {
    1: "Mesh > Clean Up > Merge by Distance and Delete Loose, then Mesh > Normals > Recalculate "
       "Outside, fix it",
    2: "turn on Close Holes in the operator's panel, or fill them (Edit Mode > Select > All by "
       "Trait > Non Manifold, then Face > Fill)",
    3: "turn on Split Non-Manifold Spots in the operator's panel",
    4: "they are kept out of the computation (to remove them: Mesh > Clean Up > Degenerate "
       "Dissolve)",
    5: "remove the doubles (Mesh > Clean Up > Merge by Distance)",
    6: "remesh the surface (Remesh modifier, then Apply) and run again",
    7: "refine it (Edit Mode > Edge > Subdivide) and run again",
    8: "set Form i and Form j to -1 in the operator's panel (a generic pair)",
    9: "shorten or thicken them, or map them as separate objects",
    10: "remove the stray vertex, or bring the coordinates to one unit (Object > Apply > Scale)",
    11: "choose Spherical UVs to pack the parts' UVs",
    12: "turn on Add Vertices Where Needed (and off Strict) in the operator's panel",
}


def remedy_words(code):
    return WORDS.get(code, "")


def with_remedies(message, codes):
    return "; ".join([message] + [remedy_words(code) for code in codes if remedy_words(code)])


def advice_words(advice):
    return "; ".join("%s: %s" % (cause, remedy_words(code)) for cause, code in advice)
