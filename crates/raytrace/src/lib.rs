//! Shared glue for the command-line programs (placeholder).
