//! parry
