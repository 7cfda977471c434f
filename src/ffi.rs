//! C boundary (placeholder)
