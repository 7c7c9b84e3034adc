// tests/scenarios/jobs/report_schema.h: a job's report.json checked against docs/schema/ by an
// independent validator (python3-jsonschema), for every test that prints a job.
#pragma once

#include <filesystem>

#include "tests/scenarios/jobs/run_command.h"
#include "tests/support/paths.h"

namespace tp::test {

/// Validates `report` against docs/schema/report.schema.json (JSON Schema 2020-12); the output
/// lists each error as "pointer: message". Exit code 0 when the report is valid.
inline CommandResult validate_report(const std::filesystem::path& report) {
  return run_command(
      {"/usr/bin/python3", "-c",
       "import json, sys, jsonschema\n"
       "schema = json.load(open(sys.argv[2]))\n"
       "jsonschema.Draft202012Validator.check_schema(schema)\n"
       "errors = list(jsonschema.Draft202012Validator(schema).iter_errors(json.load(open(sys.argv[1]))))\n"
       "for e in errors: print('/'.join(map(str, e.absolute_path)) + ': ' + e.message)\n"
       "sys.exit(1 if errors else 0)\n",
       report.string(), (source_dir() / "docs/schema/report.schema.json").string()});
}

}  // namespace tp::test
