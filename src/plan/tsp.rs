//! Rapid-path optimisation of the contour order. PLACEHOLDER until it lands.
#![allow(dead_code)]
