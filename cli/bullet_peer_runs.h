#pragma once
// Bullet runs for the reports: reports/ knows neither Bullet nor bench/, so
// the physdbg command hands them these functions. Each is empty when physdbg
// was built without Bullet, and the report then says so.
#include "reports/accuracy_references.h"
#include "reports/solver_report.h"

namespace physdbg::cli {

// The scene in bench::BulletWorld with `iterations` solver iterations,
// sleeping off, timed around its steps alone.
reports::PeerSolverRun bulletSolverRun();

// The accuracy references' scenes in bench::BulletWorld (default solver,
// sleeping off).
reports::SimulationFactory bulletSimulation();

}  // namespace physdbg::cli
