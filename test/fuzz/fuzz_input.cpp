// libFuzzer harness over the program's input path: the first byte names the
// reader (p: PLY, l: LAS, o: OFF, anything else: XYZ), the rest is the file.
// A file that reads is written back in its format and read again, which must
// give as many points, and a small one is simplified, as the program would.
// Any crash, sanitizer report, or exception other than the documented
// Read_error and std::invalid_argument is a finding.

#include "point_files.h"
#include "simplify_cloud.h"

#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace es = entropy_simplify;

namespace {

es::Format format_named(char kind)
{
  switch (kind)
  {
  case 'p': return es::Format::ply;
  case 'l': return es::Format::las;
  case 'o': return es::Format::off;
  default: return es::Format::xyz;
  }
}

void write_back_and_reread(const es::Cloud& cloud, es::Format format)
{
  std::vector<std::size_t> rows(cloud.size());
  std::iota(rows.begin(), rows.end(), std::size_t(0));
  es::String_sink out;
  if (cloud.las)
    es::write_las(out, *cloud.las, rows);
  else
    es::write_table(out, es::output_table(cloud, rows, nullptr), format, cloud.binary_ply, cloud.comments);
  if (es::read_cloud(out.bytes, format).size() != cloud.size())
    std::abort();
}

// Both modes on small clouds; the library rejects what it must with
// std::invalid_argument (too few points, coordinates beyond 1e150).
void simplify_small(const es::Cloud& cloud, bool paper_mode)
{
  if (cloud.size() < 4 || cloud.size() > 300)
    return;
  es::Settings settings;
  settings.k = 3;
  settings.count = cloud.size() / 2;
  settings.write_normals = true;
  if (paper_mode)
    settings.options.mode = es::ES::Mode::paper;
  std::vector<std::array<double, 3> > normals;
  try
  {
    const std::vector<std::size_t> kept =
      es::simplify_cloud<CGAL::Sequential_tag>(cloud, settings, std::function<bool(double)>(), normals).kept;
    if (kept.size() != *settings.count || normals.size() != kept.size())
      std::abort();
  }
  catch (const std::invalid_argument&)
  {
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size == 0)
    return 0;
  const es::Format format = format_named(char(data[0]));
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  es::Cloud cloud;
  try
  {
    cloud = es::read_cloud(bytes, format);
  }
  catch (const es::Read_error&)
  {
    return 0;
  }
  write_back_and_reread(cloud, format);
  simplify_small(cloud, (data[size - 1] & 1) != 0);
  return 0;
}
