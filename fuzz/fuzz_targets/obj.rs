//! Fuzz target: arbitrary bytes as an OBJ file through the whole reader (parser, welding, the
//! closed-solid checks) and, when it reads, the faceted engine's preparation of the mesh. Any
//! panic or abort is a bug.
#![no_main]

mod mesh_input;

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    mesh_input::read_and_prepare(data, "obj");
});
