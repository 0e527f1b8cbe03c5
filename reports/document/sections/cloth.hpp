// What the cloth's section at a frame budget (section `cloth`, made in frames.cpp) adds to the
// rope's: the cheapest set-up within 1 % of the body's size, and a picture of the cloth: the
// profile of its middle column of masses, seen from the side (y across the pinned edge, z up), at
// three frames, for the reference and each family's cheapest stable set-up. The profile is the
// line from the pinned edge to the free one through the masses whose rest x is nearest the
// middle: it shows how far the sheet has fallen and swung, in a figure that reads in print.
// Besides, the claims both sections make of a run.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "analysis/studies/frames.hpp"
#include "reports/document/section.hpp"

namespace steplab {

class Ledger;

// A frame-budget study as a section cites it: its runs, the section's id and its document.
struct FramesCited {
  const FramesResult& r;
  const std::string& section;
  std::string document;
};
// "runs[i] is the least of `among` by `field`" (error_max or spring_visits_per_frame; others
// ascending; tied where the next is equal), claimed.
void claim_least_run(Ledger& l, const FramesCited& c, std::string claim_id, std::string sentence, std::size_t i,
                     std::vector<std::size_t> among, const char* field);
// A run's cost a frame in words: its spring visits, and where timed its time.
std::string frame_cost_text(const FramesResult& r, const FrameRun& x);
// The cheapest stable set-up whose error is within kVisualTarget of the body's size at rest (an
// error the eye does not see), claimed: the least cost of those that reach it, every cheaper stable
// one above it, and its error below it; "" where a body at rest would be within it.
inline constexpr double kVisualTarget = 0.01;
std::string visual_target(Ledger* l, const FramesCited& c);

// The rope's XPBD at every split of the same budget (the frame study's default rope, XPBD
// alone, untimed, no order rows): what the cloth's "substeps or sweeps" is set against.
FramesResult rope_xpbd_study(const FramesConfig& cloth, const Workers& w);
// "XPBD at budget x 1 is X times as accurate as at 1 x budget here, Y times on the rope": each
// ratio claimed from its document (the cloth's, and `rope_document`, the rope's written beside it);
// "" where either end is unstable.
std::string xpbd_contrast(Ledger* l, const FramesCited& cloth, const FramesResult& rope, const std::string& rope_document);

struct ClothPicture {
  std::vector<long long> frames;   // the frames drawn: a third, two thirds and all of the run
  std::vector<std::size_t> runs;   // indices into FramesResult::runs, drawn beside the reference
  std::vector<std::string> drawn;  // their methods' names
  // per curve (the reference, then runs), per frame drawn: the profile's points (y, z)
  std::vector<std::vector<std::vector<std::array<double, 2>>>> profiles;
};

ClothPicture cloth_picture(const FramesResult& r);
// data/<section>/profile_reference.dat and profile_<method>.dat: a block of "y z" a frame drawn.
void write_picture(const ClothPicture& p, const DataDir& dat);
FigureSpec picture_figure(const ClothPicture& p, const FramesResult& r);
// Its figure and caption, the caption's sentence a claim over the drawn set-ups' errors.
std::string picture_markdown(Page& page, const ClothPicture& p, const FramesResult& r, const std::string& section,
                             const std::string& document);

}  // namespace steplab
