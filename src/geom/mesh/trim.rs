//! Trimming (paper 001's "split at once") — placeholder module filled in below.
