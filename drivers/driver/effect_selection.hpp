#pragma once
// The active effect set of a scene (docs/design.md section 5): derived from the materials, masked by
// what the model implements, or overridden in [model] effects. Also the storage it implies.
#include <epac/models/effects.hpp>
#include <epac/params/material.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace epac {
namespace driver {

// "friction, damping" ("none" for the empty set).
std::string effect_names(unsigned bits);

// Bit of one effect name ("adhesion", "plasticity", "friction", "damping", "radius_growth",
// "rolling");
// 0 if unknown.
unsigned effect_bit(const std::string& name);

// The minimal set for the pairs that can meet: every particle material with every particle
// material and every wall material. surface energy > 0 -> adhesion; finite yield stress ->
// plasticity; friction > 0 -> friction; restitution < 1 -> damping; rolling_friction > 0 ->
// rolling (the pair's geometric mean, so both materials must set it). Radius growth is a model's
// choice (MDR), never derived from materials.
unsigned derive_effects(const std::vector<Material>& materials, const std::vector<int>& particle_materials,
                        const std::vector<int>& wall_materials);

// Stored bytes per contact: history fields x sizeof(T), plus its 8-byte key when it has
// history, plus the two int indices of the contact list.
std::size_t bytes_per_contact(int history_fields, std::size_t scalar_size);
std::string bytes_per_contact_text(int history_fields, std::size_t scalar_size);

}  // namespace driver
}  // namespace epac
