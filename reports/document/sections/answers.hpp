// The answers the report opens with (answers.cpp), each a bullet computed from the data and
// claimed: the hand-out's brief sections end with theirs ("" where the report did not run the study).
#pragma once

#include <cstddef>
#include <string>

#include "reports/document/section.hpp"

namespace steplab {

std::string stiff_answer(const Page& page);      // does the order hold when stiff?
std::string cost_answer(const Page& page);       // what does accuracy cost?
std::string implicit_answer(const Page& page);   // when does implicit pay?
std::string long_time_answer(const Page& page);  // stable for how long?

// The name of a scene's work-precision figure (the cost section draws one a scene).
std::string work_precision_figure(std::size_t scene);

// The bullet as a paragraph: "**Question?** answer.\n".
std::string answer_paragraph(const std::string& bullet);

}  // namespace steplab
