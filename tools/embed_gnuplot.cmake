# Writes a C++ header holding every reports/document/gnuplot/*.gp script as a string, so the steplab
# binary draws its figures from anywhere. Called by CMake with -DOUT=header -DIN="a.gp|b.gp".
set(body "// Generated from reports/document/gnuplot/*.gp by tools/embed_gnuplot.cmake. Do not edit.\n#pragma once\n#include <array>\n#include <string_view>\nnamespace steplab {\nstruct GnuplotScript { std::string_view name, text; };\ninline constexpr std::array gnuplot_scripts{\n")
string(REPLACE "|" ";" IN "${IN}")
list(SORT IN)
foreach(f IN LISTS IN)
  get_filename_component(stem ${f} NAME_WE)
  file(READ ${f} text)
  string(APPEND body "  GnuplotScript{\"${stem}\", R\"GP(${text})GP\"},\n")
endforeach()
string(APPEND body "};\n}  // namespace steplab\n")
file(WRITE ${OUT} "${body}")
