#pragma once
// pipes.csv: the pipes of a 2D or 3D run over time (physics/Pipes.hpp; docs/case-format.md).
// Written through SeriesWriter, so that it is flushed line by line and cut back on a resume like
// series.csv. One line per pipe and output time, largest flux share first; a time without pipes
// has one line with pipe = 0 and the pipe's columns empty (nan).
//
//   time                  s
//   pipes                 -, the number of pipes now
//   fluidised_flux_share  -, share of the water crossing the filter through open base cells
//                         (fluidised, or a pocket of water: physics/Pipes.hpp)
//   pipe                  -, 1.. (0: none)
//   x, y                  m, the pipe's centroid (y in 3D only; x is the radius in axisymmetry)
//   width, height         m, mean width (3D: equivalent diameter) and top above the filter
//   wall                  1 if it lies against a side wall, else 0
//   flux_share            -, share of the water crossing the filter through its base cells
//   cells                 -, its number of cells
#include <cmath>
#include <string>
#include <vector>

#include "physics/Pipes.hpp"

namespace qs {

inline std::vector<std::string> pipesColumns(int dimension) {
    std::vector<std::string> c = {"time", "pipes", "fluidised_flux_share", "pipe", "x"};
    if (dimension == 3) c.push_back("y");
    for (const char* name : {"width", "height", "wall", "flux_share", "cells"}) c.push_back(name);
    return c;
}

inline std::vector<std::vector<double>> pipesRows(double time, int dimension, const PipeSurvey& survey) {
    std::vector<std::vector<double>> rows;
    const double count = static_cast<double>(survey.pipes.size());
    if (survey.pipes.empty()) {
        std::vector<double> row = {time, 0.0, survey.fluidisedFluxShare, 0.0};
        row.resize(pipesColumns(dimension).size(), std::nan(""));
        rows.push_back(row);
    }
    for (std::size_t k = 0; k < survey.pipes.size(); ++k) {
        const Pipe& p = survey.pipes[k];
        std::vector<double> row = {time, count, survey.fluidisedFluxShare, double(k + 1), p.x};
        if (dimension == 3) row.push_back(p.y);
        for (double v : {p.width, p.height, p.wall ? 1.0 : 0.0, p.fluxShare, double(p.cellCount)}) row.push_back(v);
        rows.push_back(row);
    }
    return rows;
}

}  // namespace qs
