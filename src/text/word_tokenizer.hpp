// Captions -> GloVe word indices. GloVe's vocabulary is lower-case with punctuation as separate tokens, so the
// tokenizer lower-cases ASCII letters and splits at whitespace and before/after every punctuation character
// except an apostrophe inside a word and a hyphen between letters ("counter-clockwise", "person's").
//
// Unknown words: a word missing from the vocabulary is looked up again without a possessive "'s", then as its
// hyphen-separated parts, then with a trailing "s", "ed" or "ing" removed (the lemma often is in the 100k); what
// is still unknown is returned as index -1. The sentence similarity skips it; the trainable text encoder maps it
// to a learned <unk> vector.
#pragma once
#include <string>
#include <vector>

#include "text/word_vectors.hpp"

namespace t2imu {

std::vector<std::string> split_words(const std::string& text);
std::vector<int> word_indices(const std::string& text, const WordVectors& vocabulary);

// The words of `vectors` that the lines of `paths` (text files, or folders searched for *.txt) resolve to, in
// rank order: a small vocabulary to carry to a training machine. The trainable text encoder gives every caption
// of those files the same input with this subset as with the full vocabulary, since each caption word resolves
// to a word the subset keeps; SIF weights (rank-based) differ.
WordVectors vocabulary_used_in(const WordVectors& vectors, const std::vector<std::string>& paths);

}  // namespace t2imu
