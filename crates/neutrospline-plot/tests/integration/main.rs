//! The integration tests of neutrospline-plot, one binary: one module per topic.

mod band;
mod browser;
mod data;
mod display_list;
mod families;
mod print;
mod score;
mod surfaces;
mod views;
mod wide;
