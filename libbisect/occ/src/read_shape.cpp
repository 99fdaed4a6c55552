// Reading a shape from a BREP, STEP or IGES file, or from a BREP string.
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <TopoDS_Iterator.hxx>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>

#include "bisect/occ.hpp"
#include "occ_guard.hpp"
#include "occ_shape.hpp"

namespace bisect {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

bool is_empty(const TopoDS_Shape& s) { return s.IsNull() || (s.ShapeType() <= TopAbs_COMPSOLID && !TopoDS_Iterator(s).More()); }

// The data-exchange readers keep their settings in process-wide statics (Interface_Static), which
// FreeCAD's own importers share: one reader at a time, and the length unit put back afterwards.
std::mutex& exchange_mutex() {
  static std::mutex m;
  return m;
}

class MillimetreUnit {
 public:
  MillimetreUnit() {
    const char* old = Interface_Static::CVal("xstep.cascade.unit");
    if (old) old_ = old;
    Interface_Static::SetCVal("xstep.cascade.unit", "MM");
  }
  ~MillimetreUnit() {
    if (!old_.empty()) Interface_Static::SetCVal("xstep.cascade.unit", old_.c_str());
  }

 private:
  std::string old_;
};

template <class Reader>
TopoDS_Shape read_exchange_file(const std::string& path, const char* format) {
  std::lock_guard<std::mutex> lock(exchange_mutex());
  Reader reader;  // constructing it registers the format's statics
  const MillimetreUnit mm;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
    throw InputError(path + ": not a readable " + format + " file");
  reader.TransferRoots();
  return reader.OneShape();
}

// An InputError that names the source first.
[[noreturn]] void rethrow_named(const InputError& e, const std::string& source) {
  const std::string m = e.what();
  if (m.rfind(source + ":", 0) == 0) throw e;
  throw InputError(source + ": " + m);
}

BrepInput to_input(const TopoDS_Shape& shape, const std::string& source) {
  try {
    return occ::brep_input_from_shape(shape, source);
  } catch (const InputError& e) {
    rethrow_named(e, source);
  }
}

}  // namespace

bool is_brep_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".brep" || ext == ".brp" || ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs";
}

BrepInput load_brep_file(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (!is_brep_path(path))
    throw InputError(path + ": not a B-rep file (the extension must be .brep, .brp, .step, .stp, .iges or .igs)");
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe) throw InputError(path + ": cannot open the file");
    if (std::filesystem::is_directory(path)) throw InputError(path + ": is a directory, not a file");
  }
  TopoDS_Shape shape;
  const char* format = ext == ".step" || ext == ".stp" ? "STEP" : ext == ".iges" || ext == ".igs" ? "IGES" : "BREP";
  occ::guard([&] { return path; }, (std::string("OpenCASCADE could not read it as ") + format).c_str(), [&] {
    if (ext == ".step" || ext == ".stp") {
      shape = read_exchange_file<STEPControl_Reader>(path, "STEP");
    } else if (ext == ".iges" || ext == ".igs") {
      shape = read_exchange_file<IGESControl_Reader>(path, "IGES");
    } else {
      BRep_Builder builder;
      if (!BRepTools::Read(shape, path.c_str(), builder)) throw InputError(path + ": not a readable BREP file");
    }
  });
  if (is_empty(shape)) throw InputError(path + ": the " + format + " file holds no shape");
  return to_input(shape, path);
}

BrepInput load_brep_string(const std::string& brep, const std::string& name) {
  if (brep.empty()) throw InputError(name + ": the BREP string is empty");
  TopoDS_Shape shape;
  occ::guard([&] { return name; }, "OpenCASCADE could not read the BREP string", [&] {
    std::istringstream in(brep);
    BRep_Builder builder;
    BRepTools::Read(shape, in, builder);
  });
  if (is_empty(shape)) throw InputError(name + ": the BREP string holds no shape");
  return to_input(shape, name);
}

}  // namespace bisect
