// The picture at the end of a run (output.picture, docs/case-files.md): a cut through the model, drawn
// with gnuplot (pngcairo). Host only.
//
// The cut is the first symmetry plane that contains the impact direction (x = 0 of the quarter plate),
// or else the plane through the projectile's centre of mass normal to the axis the projectile moves
// least along (x for an impact along z). Of each body, the layer of particles nearest that plane is
// drawn (centres within half a spacing of the layer), as squares one lattice spacing wide in mm, with
// equal axis scales, coloured by output.picture_field (plastic strain by default). A symmetry plane
// across the picture that contains the impact direction (y = 0 of the quarter plate) mirrors the cut, so
// the whole section shows. Failed particles (D >= 0.99) are drawn in colours of their own (blue, the
// projectile's green), the projectile's squares outlined when there are other bodies; the title gives the
// time and the cut, a bar the scale.
#pragma once
#include <filesystem>
#include <string>

#include "common/case_spec.hpp"
#include "common/particle_set.hpp"
#include "common/scene.hpp"

namespace impactsph {

// Writes DIR/STEM.dat (the particles of the cut) and DIR/STEM.gp (its gnuplot script, which names no
// other path: `gnuplot STEM.gp` in DIR draws STEM.png). `time` in s. Throws std::runtime_error when no
// particle lies in the cut or a file cannot be written.
void write_picture_files(const std::filesystem::path& dir, const std::string& stem, const Scene& scene,
                         const ParticleSet& p, double time, PictureField field);

// Draws DIR/STEM.png from the files write_picture_files wrote. Returns an error message, or "" when the
// PNG is there.
std::string draw_picture(const std::filesystem::path& dir, const std::string& stem);

// What the picture is coloured by, with its unit: "plastic strain [-]".
std::string picture_field_label(PictureField field);

// Both; never throws (a picture must not fail a run). Returns a one-line warning, or "" when the PNG is
// there.
std::string write_and_draw_picture(const std::filesystem::path& dir, const std::string& stem, const Scene& scene,
                                   const ParticleSet& p, double time, PictureField field);

}  // namespace impactsph
