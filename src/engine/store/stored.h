// A derivation as text, so that a regeneration need not derive again a file that has not
// changed (the pipeline keeps it in its cache, src/cache/store.h, keyed by the file's bytes
// and those of the files it uses; engine/library/library.h).
//
// Every expression is kept exactly, as GiNaC's own objects: sums, products, powers,
// functions, relations and lists by their operands, numbers as exact rationals (or
// complex ones), the derivation's symbols by their place in its symbol table and any
// other symbol (one a proof made: a magnitude, the t of s = 1/t) by its class, name and
// TeX name, one object for each the derivation held. Expressions shared between parts of
// the derivation are written once. What the derivation was derived from, the
// `spec::derivation`, is not kept: it is the file, read again; the bytes of each file its
// places name are, so that a place is moved to where it is now when comments were added
// or removed above it (the pipeline keys a derivation by its file without comments).
//
// A derivation restored from its text is the one that was derived: every later stage
// prints the same bytes from it (tests/test_cache.cpp regenerates from restored
// derivations and compares).
#pragma once

#include "engine/derivation/derivation.h"
#include "spec/derivation.h"

#include <optional>
#include <string>

namespace impact::engine {

/// `d` as text (with the bytes of its file and of those in `done` that its places name);
/// nothing when it holds what cannot be kept exactly (a floating-point number, a kind of
/// GiNaC object no derivation makes), and it is then derived again on every run.
std::optional<std::string> stored_derivation(const derivation& d, const derived_by_id& done = {});

/// The derivation that `text` holds, `source` being the file it was derived from and `done`
/// those it uses; nothing when `text` is not one that `stored_derivation` wrote for this
/// version of Impact (damaged, truncated, or of another format). Its places (file, line and
/// column, as messages name them) are those of the files now: a file that changed only by
/// lines of comments or spaces has the places after them moved; one that changed otherwise
/// (a line's text, the order of its keys) gives nothing.
std::optional<derivation> restored_derivation(const std::string& text, const spec::derivation& source,
                                             const derived_by_id& done = {});

} // namespace impact::engine
