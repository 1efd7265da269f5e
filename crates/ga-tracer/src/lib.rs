//! ga-tracer (placeholder: being written).
#![deny(missing_docs)]
