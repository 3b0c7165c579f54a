//! Public-API tests of envmap, one binary.

mod data;
