// The automatic table's evidence (lut_auto_evidence.h).
#include "lut_auto_evidence.h"

#include "visioncore/basics/colour_lut.h"

#include <Eigen/LU>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace fieldsight::autolut {

Gaussian Moments::gaussian(const Eigen::Vector3d& floor) const
{
    Gaussian g;
    if (n < 3)
        return g;
    g.mean = Eigen::Map<const Eigen::Vector3d>(sum) / n;
    g.covariance =
        Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(&outer[0][0]) / n -
        g.mean * g.mean.transpose();
    g.covariance.diagonal() += floor;
    g.inverse = g.covariance.inverse();
    g.valid = g.inverse.allFinite();
    return g;
}

Colour evidenceColour(Evidence e)
{
    switch (e) {
    case Evidence::Green:
        return Colour::Green;
    case Evidence::White:
        return Colour::White;
    case Evidence::Orange:
        return Colour::Orange;
    case Evidence::Yellow:
        return Colour::Yellow;
    case Evidence::Blue:
        return Colour::Blue;
    default:
        return Colour::Unclassified;
    }
}

void EvidenceSet::add(Evidence e, const std::uint8_t* px)
{
    auto& counts = cells[std::uint32_t(ColourLut::index(px[0], px[1], px[2]))];
    ++counts[std::size_t(e)];
    moments[std::size_t(e)].add(px);
}

void EvidenceSet::addCell(Evidence e, std::uint32_t cell, std::uint32_t count)
{
    cells[cell][std::size_t(e)] += count;
    moments[std::size_t(e)].add(((cell >> 14) & 127) * 2 + 1, ((cell >> 7) & 127) * 2 + 1,
                                (cell & 127) * 2 + 1, count);
}

namespace {

constexpr double kCarpetLimit = 3.0; ///< Mahalanobis distance of a carpet pixel

} // namespace

std::optional<Gaussian> findCarpet(const std::vector<cv::Mat>& frames, const std::vector<int>& tops)
{
    // The chroma histogram of the lower parts, at the table's resolution.
    cv::Mat hist(128, 128, CV_32F, cv::Scalar(0));
    forLowerPixels(frames, tops,
                   [&](const std::uint8_t* px) { hist.at<float>(px[1] >> 1, px[2] >> 1) += 1; });
    cv::GaussianBlur(hist, hist, cv::Size(5, 5), 1.5);
    cv::Point peak;
    double most = 0;
    cv::minMaxLoc(hist, nullptr, &most, nullptr, &peak);
    if (most <= 0)
        return std::nullopt;
    const double peak_cb = peak.y * 2 + 1;
    const double peak_cr = peak.x * 2 + 1;

    // Grow a Gaussian from the pixels near the peak, then from those within the limit.
    const Eigen::Vector3d floor(9, 4, 4);
    Gaussian g;
    for (int round = 0; round < 4; ++round) {
        Moments m;
        forLowerPixels(frames, tops, [&](const std::uint8_t* px) {
            const bool near = round == 0
                                  ? std::abs(px[1] - peak_cb) <= 8 && std::abs(px[2] - peak_cr) <= 8
                                  : g.distance2(px[0], px[1], px[2]) <= kCarpetLimit * kCarpetLimit;
            if (near)
                m.add(px);
        });
        if (m.n < 50)
            return std::nullopt;
        g = m.gaussian(floor);
        // A sample cut at the limit underestimates the spread (chi-square, 3 degrees: about 9%).
        g.covariance *= 1.1;
        g.inverse = g.covariance.inverse();
    }
    return g;
}

namespace {

enum class Hue { None, Warm, Pink, Yellow, Blue };

/// Where a warm hue turns from the ball's orange to a team's pink (degrees, as hueOf). The ball is
/// orange, on the yellow side of red (full red is at 109 here); a team's pink band is on the blue
/// side (about 75-80 on the generated robots). The split leaves 15-20 on either side of what the
/// streams show: NUbots' reddish ball at 114-118 and B-Human's at 125-133 (a red arm's rims at
/// 107-110), the generated balls at 131-133.
constexpr double kPinkBelow = 95;

/// The hue family of a saturated pixel: warm (orange, red), pink (a team's colour), yellow, or
/// blue.
Hue hueOf(const std::uint8_t* px)
{
    const double cb = px[1] - 128.0;
    const double cr = px[2] - 128.0;
    if (px[0] < 24 || cb * cb + cr * cr < 14.0 * 14.0)
        return Hue::None;
    double a = std::atan2(cr, cb) * 180 / M_PI; // 0: blue, 90: red, 180: yellow, -120: green
    if (a < -150)
        a += 360;
    if (a >= 60 && a < kPinkBelow)
        return Hue::Pink;
    if (a >= kPinkBelow && a < 150)
        return Hue::Warm;
    if (a >= 150 && a <= 208)
        return Hue::Yellow;
    if (a >= -80 && a < 40)
        return Hue::Blue;
    return Hue::None;
}

struct Blob
{
    cv::Rect box;
    int area = 0;
};

/// Adds a component's pixels as `e`: its inner pixels (all four neighbours in it) when it is
/// large enough to have them, so the rims blended with what surrounds it do not count.
std::size_t addComponent(const cv::Mat& ycbcr, const cv::Mat& labels, int label, const Blob& blob,
                         Evidence e, double scale, EvidenceSet& out,
                         const std::vector<bool>& columns = {})
{
    std::size_t added = 0;
    const bool inner_only = blob.area >= 40 * scale * scale;
    const cv::Rect& r = blob.box;
    for (int y = r.y; y < r.y + r.height; ++y) {
        for (int x = r.x; x < r.x + r.width; ++x) {
            if (labels.at<int>(y, x) != label ||
                (!columns.empty() && !columns[std::size_t(x - r.x)]))
                continue;
            if (inner_only &&
                (x == 0 || y == 0 || x + 1 >= labels.cols || y + 1 >= labels.rows ||
                 labels.at<int>(y - 1, x) != label || labels.at<int>(y + 1, x) != label ||
                 labels.at<int>(y, x - 1) != label || labels.at<int>(y, x + 1) != label))
                continue;
            out.add(e, ycbcr.ptr<std::uint8_t>(y) + 3 * x);
            ++added;
        }
    }
    return added;
}

/// The share of carpet in a ring around `box` (inside the image): a ball lies on the carpet.
double greenAround(const cv::Mat& green, const cv::Rect& box)
{
    const int grow = std::max(2, std::max(box.width, box.height) / 4);
    const cv::Rect ring =
        cv::Rect(box.x - grow, box.y - grow, box.width + 2 * grow, box.height + 2 * grow) &
        cv::Rect(0, 0, green.cols, green.rows);
    std::size_t all = 0;
    std::size_t carpet = 0;
    for (int y = ring.y; y < ring.y + ring.height; ++y) {
        const std::uint8_t* row = green.ptr<std::uint8_t>(y);
        for (int x = ring.x; x < ring.x + ring.width; ++x) {
            if (box.contains({x, y}))
                continue;
            ++all;
            carpet += row[x] != 0;
        }
    }
    return all ? double(carpet) / double(all) : 0;
}

/// The median length of the runs of `label` across the rows of `box`.
double medianRun(const cv::Mat& labels, int label, const cv::Rect& box)
{
    std::vector<int> runs;
    for (int y = box.y; y < box.y + box.height; ++y) {
        const int* row = labels.ptr<int>(y);
        for (int x = box.x; x < box.x + box.width;) {
            if (row[x] != label) {
                ++x;
                continue;
            }
            int end = x;
            while (end + 1 < box.x + box.width && row[end + 1] == label)
                ++end;
            runs.push_back(end - x + 1);
            x = end + 1;
        }
    }
    if (runs.empty())
        return 0;
    std::nth_element(runs.begin(), runs.begin() + std::ptrdiff_t(runs.size() / 2), runs.end());
    return runs[runs.size() / 2];
}

/// The columns of a bar-shaped component that are posts: they reach down to the field's edge (a
/// wall of the same colour joined to a post, and the crossbar, do not), and each run of such
/// columns is at least three times as tall as it is wide (a wall or curtain standing along the
/// field's edge is not).
std::vector<bool> postColumns(const cv::Mat& labels, int label, const cv::Rect& box,
                              const std::vector<double>& edge, int h)
{
    std::vector<bool> columns(std::size_t(box.width), false);
    std::vector<int> lowest(std::size_t(box.width), -1);
    std::vector<int> highest(std::size_t(box.width), -1);
    for (int x = box.x; x < box.x + box.width; ++x) {
        for (int y = box.y; y < box.y + box.height; ++y) {
            if (labels.at<int>(y, x) != label)
                continue;
            if (highest[std::size_t(x - box.x)] < 0)
                highest[std::size_t(x - box.x)] = y;
            lowest[std::size_t(x - box.x)] = y;
        }
        const int foot = lowest[std::size_t(x - box.x)];
        columns[std::size_t(x - box.x)] = foot >= 0 && foot >= edge[std::size_t(x)] - 0.05 * h;
    }
    for (int start = 0; start < box.width;) {
        if (!columns[std::size_t(start)]) {
            ++start;
            continue;
        }
        int end = start;
        while (end + 1 < box.width && columns[std::size_t(end + 1)])
            ++end;
        int top = h;
        int foot = 0;
        for (int c = start; c <= end; ++c) {
            top = std::min(top, highest[std::size_t(c)]);
            foot = std::max(foot, lowest[std::size_t(c)]);
        }
        // A post cut by the top of the image shows less of its height.
        if (foot - top + 1 < (top == 0 ? 2 : 3) * (end - start + 1))
            for (int c = start; c <= end; ++c)
                columns[std::size_t(c)] = false;
        start = end + 1;
    }
    return columns;
}

/// Sorts the saturated shapes of one hue family: round blobs on the field (warm: the ball; pink: a
/// team's band, never the ball), bars standing at the field's edge (yellow, blue: a goal), the
/// rest touching the field background (warm ones apart: WarmShape).
void sortShapes(const cv::Mat& ycbcr, const cv::Mat& green, const cv::Mat& mask, Hue hue,
                const std::vector<double>& edge, double scale, EvidenceSet& out)
{
    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
    const int w = mask.cols;
    const int h = mask.rows;
    for (int i = 1; i < n; ++i) {
        Blob b;
        b.box = cv::Rect(stats.at<int>(i, cv::CC_STAT_LEFT), stats.at<int>(i, cv::CC_STAT_TOP),
                         stats.at<int>(i, cv::CC_STAT_WIDTH), stats.at<int>(i, cv::CC_STAT_HEIGHT));
        b.area = stats.at<int>(i, cv::CC_STAT_AREA);
        if (b.area < 6 * scale * scale)
            continue;
        const int bottom = b.box.y + b.box.height - 1;
        const double edge_at = edge[std::size_t(b.box.x + b.box.width / 2)];
        if (edge_at >= h)
            continue; // no field in this column
        const bool on_field = bottom >= edge_at + 1;
        const bool at_border =
            b.box.x == 0 || b.box.y == 0 || b.box.x + b.box.width == w || bottom == h - 1;
        const double aspect = double(b.box.width) / b.box.height;
        const double fill = double(b.area) / (double(b.box.width) * b.box.height);
        if (hue == Hue::Warm || hue == Hue::Pink) {
            // Round: a disc fills about 0.79 of its box; one cut by the image's side less. A
            // wide shape along the bottom is the robot's own body.
            const double fill_needed = at_border ? 0.5 : 0.6;
            const bool shaped =
                at_border ? aspect >= 0.4 && aspect <= 2.5 : aspect >= 0.5 && aspect <= 2.0;
            const bool own_body = bottom == h - 1 && b.box.width >= 0.25 * w;
            const bool round = shaped && fill >= fill_needed && !own_body &&
                               b.area >= 12 * scale * scale && b.box.width <= 0.6 * w &&
                               greenAround(green, b.box) >= 0.25;
            if (round && on_field && hue == Hue::Warm) {
                addComponent(ycbcr, labels, i, b, Evidence::Orange, scale, out);
                out.ball_blobs += 1;
            } else if (bottom >= edge_at - 2) {
                addComponent(ycbcr, labels, i, b,
                             hue == Hue::Warm ? Evidence::WarmShape : Evidence::Background, scale,
                             out);
            }
            continue;
        }
        // A post is much taller than it is thick; a goal's crossbar makes a few long rows, so
        // the thickness is the median width of the shape's runs.
        if (bottom >= edge_at - 0.1 * h)
            out.goal(hue == Hue::Yellow ? Evidence::Yellow : Evidence::Blue).shapes += b.area;
        const double thickness = medianRun(labels, i, b.box);
        // A post is about eight times as tall as it is thick; one cut by the top of the image
        // may show less of its height.
        const bool bar =
            b.box.height >= 10 * scale && b.box.height >= (b.box.y == 0 ? 3 : 4) * thickness;
        // Its foot is at the field's far edge (on the goal line, a little in front of it), not
        // on the field near the camera (a person's legs) nor up on the wall.
        const bool stands = bottom >= edge_at - 0.05 * h && b.box.y <= edge_at;
        if (bar && stands) {
            const Evidence e = hue == Hue::Yellow ? Evidence::Yellow : Evidence::Blue;
            // Only the columns that reach down to the field's edge are the posts: a wall of
            // the same colour joined to a post, or the crossbar, are not sampled.
            const std::vector<bool> columns = postColumns(labels, i, b.box, edge, h);
            const std::size_t sampled = addComponent(ycbcr, labels, i, b, e, scale, out, columns);
            out.goal(e).posts += double(sampled);
        } else if (on_field) {
            // A door, a cupboard, a jersey: the goal's colour must not reach it.
            addComponent(ycbcr, labels, i, b, Evidence::Background, scale, out);
        }
    }
}

} // namespace

void collectEvidence(const cv::Mat& ycbcr, const Gaussian& carpet, EvidenceSet& out)
{
    const int w = ycbcr.cols;
    const int h = ycbcr.rows;
    const double scale = w / 320.0;
    cv::Mat green(h, w, CV_8U, cv::Scalar(0));
    cv::Mat candidate(h, w, CV_8U, cv::Scalar(0));
    const double bright = carpet.mean[0] + std::max(30.0, 3 * std::sqrt(carpet.covariance(0, 0)));
    // White: unsaturated, or (a thin line whose chroma the camera blended with the carpet's)
    // towards the carpet's hue and well short of its saturation.
    const double carpet_cb = carpet.mean[1] - 128;
    const double carpet_cr = carpet.mean[2] - 128;
    const double carpet_chroma = std::hypot(carpet_cb, carpet_cr);
    const auto whiteish = [&](const std::uint8_t* px) {
        const double cb = px[1] - 128.0;
        const double cr = px[2] - 128.0;
        const double chroma = std::hypot(cb, cr);
        if (chroma <= 18)
            return true;
        return chroma <= 0.6 * carpet_chroma &&
               cb * carpet_cb + cr * carpet_cr >= 0.7 * chroma * carpet_chroma;
    };
    for (int y = 0; y < h; ++y) {
        const std::uint8_t* row = ycbcr.ptr<std::uint8_t>(y);
        for (int x = 0; x < w; ++x) {
            const std::uint8_t* px = row + 3 * x;
            if (carpet.distance2(px[0], px[1], px[2]) <= kCarpetLimit * kCarpetLimit)
                green.at<std::uint8_t>(y, x) = 1;
            else if (px[0] >= bright && whiteish(px))
                candidate.at<std::uint8_t>(y, x) = 1;
        }
    }
    const std::vector<double> edge = fieldEdge(green, scale);
    if (edge.front() >= h && edge.back() >= h &&
        std::all_of(edge.begin(), edge.end(), [h](double e) { return e >= h; }))
        return; // no field seen

    cv::Mat white(h, w, CV_8U, cv::Scalar(0));
    thinRuns(candidate, green, edge, scale, white);

    std::array<cv::Mat, 5> hue_masks;
    for (cv::Mat& m : hue_masks)
        m = cv::Mat(h, w, CV_8U, cv::Scalar(0));
    for (int y = 0; y < h; ++y) {
        const std::uint8_t* row = ycbcr.ptr<std::uint8_t>(y);
        for (int x = 0; x < w; ++x) {
            const std::uint8_t* px = row + 3 * x;
            if (green.at<std::uint8_t>(y, x)) {
                if (y >= edge[std::size_t(x)] && ((x ^ y) & 1) == 0)
                    out.add(Evidence::Green, px);
                continue;
            }
            if (white.at<std::uint8_t>(y, x)) {
                out.add(Evidence::White, px);
                continue;
            }
            const Hue hue = hueOf(px);
            if (hue != Hue::None)
                hue_masks[std::size_t(hue)].at<std::uint8_t>(y, x) = 1;
        }
    }
    for (const Hue hue : {Hue::Warm, Hue::Pink, Hue::Yellow, Hue::Blue})
        sortShapes(ycbcr, green, hue_masks[std::size_t(hue)], hue, edge, scale, out);
}

} // namespace fieldsight::autolut
