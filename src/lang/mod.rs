//! The language: reader, values, compiler, evaluator, errors.
