// The Dutch Nao Team's hand labels of their 2013 field pictures (IntelligentRoboticsLab/Datasets,
// NaoLeague/FieldPictures): one line per picture, `'<picture name> [K<x,y>;K<x,y>;...]'`, points
// in px from the top-left; G a goal-post foot, U a post top, L, T and X line crossings. Read here
// and turned into goalpost truth (docs/formats.md, "Importing the Dutch Nao Team's labels").
#pragma once

#include "visioncore/io/annotations.h"
#include "visioncore/io/stream_reader.h"

#include <cstddef>
#include <string>
#include <vector>

namespace fieldsight {

struct DntPoint
{
    char label = 0; ///< G, U, L, T or X (another letter is refused)
    int x = 0;      ///< px
    int y = 0;      ///< px
};

/// One picture's labels.
struct DntPicture
{
    std::string name; ///< the picture's name as the file gives it ("000001 -280 0 0 ... .png")
    std::vector<DntPoint> points;
    std::size_t line = 0; ///< 1-based, for messages

    /// The picture's number, the name's first word ("000001"): the renamed copies are
    /// "<number>.png".
    std::string number() const;
};

/// Parses a label file's text; a line that is not `'<name> [<points>]'`, a label of another
/// letter than G, U, L, T, X, or more than 64 post labels (G, U) on a line is an Error naming
/// `source`, the line and what is wrong (escaped). Blank lines and a leading UTF-8 byte order
/// mark are skipped. Linear in the text.
Result<std::vector<DntPicture>> parseDntLabels(const std::string& text, const std::string& source);
/// Reads and parses the label file at `path` (at most 4 MiB; the two files are 3 and 10 KB).
Result<std::vector<DntPicture>> loadDntLabels(const std::string& path);

/// How posts are sized where the labels leave it open.
struct DntPostModel
{
    double height_per_width = 7.0;    ///< a post's image height over its width (foot to top)
    double separation_per_width = 13; ///< the two feet's distance over a post's width
    int default_width = 10;           ///< px, a post with nothing else in its picture to size it
};

struct DntImport
{
    Annotations annotations;
    std::size_t pictures = 0;               ///< label lines whose picture is in the stream
    std::size_t posts = 0;                  ///< goalposts made
    std::vector<std::string> not_in_stream; ///< label lines' pictures the stream lacks
};

/// Goalpost truth from `pictures` for the frames of `reader` (a picture is the frame named
/// "<number>.<any extension>", or its full name): each foot G paired with the top U above it
/// (nearest in x, within max(8 px, a quarter of the height)), made a box (docs/formats.md), and
/// every labelled frame marked reviewed for goalposts (not done: other kinds are not labelled).
/// A picture the stream lacks is listed, not an error; none in the stream, or two lines of one
/// frame, is an Error naming `source`.
Result<DntImport> importDntGoalposts(const std::vector<DntPicture>& pictures,
                                     const StreamReader& reader, const std::string& source,
                                     const DntPostModel& model = {});

} // namespace fieldsight
