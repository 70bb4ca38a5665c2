// cv::Mat <-> QImage conversions for the GUI and the Qt overlay renderer.
#include "ui/adapters/image_adapter.h"

#include "visioncore/basics/ycbcr.h"

#include <QPainter>
#include <QPixmap>

#include <opencv2/imgproc.hpp>

#include <algorithm>

namespace fieldsight::ui {

QImage ycbcrToQImage(const cv::Mat& ycbcr)
{
    if (ycbcr.empty() || ycbcr.type() != CV_8UC3)
        return {};
    return bgrToQImage(ycbcrToBgr(ycbcr));
}

QImage ycbcrToZoomedQImage(const cv::Mat& ycbcr, int scale)
{
    if (ycbcr.empty() || ycbcr.type() != CV_8UC3)
        return {};
    scale = std::max(1, scale);
    // Format_RGB32 stores 0xffRRGGBB words, which a little-endian machine keeps as the bytes B, G,
    // R, 255 of OpenCV's BGRA; so the zoom writes straight into the image (one large buffer, not
    // three: fresh pages for large buffers cost more than the conversion itself).
    static_assert(Q_BYTE_ORDER == Q_LITTLE_ENDIAN, "Format_RGB32 is written as BGRA bytes");
    QImage image(ycbcr.cols * scale, ycbcr.rows * scale, QImage::Format_RGB32);
    if (image.isNull()) // out of memory for a huge zoom
        return image;
    cv::Mat target(image.height(), image.width(), CV_8UC4, image.bits(),
                   std::size_t(image.bytesPerLine()));
    cv::Mat bgra = scale == 1 ? target : cv::Mat(ycbcr.size(), CV_8UC4);
    ycbcrToBgra(ycbcr, bgra); // one pass, straight into the image at scale 1
    if (scale > 1)
        cv::resize(bgra, target, target.size(), 0, 0, cv::INTER_NEAREST);
    return image;
}

QImage bgrToQImage(const cv::Mat& bgr)
{
    if (bgr.empty() || bgr.type() != CV_8UC3)
        return {};
    QImage image(bgr.cols, bgr.rows, QImage::Format_RGB888);
    if (image.isNull())
        return image;
    // cvtColor writes straight into the QImage's own rows (their padding included in the step), so
    // the result is a deep copy without a second buffer.
    cv::Mat rgb(bgr.rows, bgr.cols, CV_8UC3, image.bits(), std::size_t(image.bytesPerLine()));
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
    return image;
}

QColor toQColor(Rgb colour)
{
    return QColor(colour.r, colour.g, colour.b);
}

} // namespace fieldsight::ui

namespace fieldsight::ui {

QString colourLabel(Colour colour)
{
    const std::string_view name = colourName(colour);
    return QString::fromUtf8(name.data(), qsizetype(name.size()));
}

QString perceptNoun(const PerceptKind& kind)
{
    QString noun = QString::fromUtf8(kind.title.data(), qsizetype(kind.title.size()));
    if (noun.size() > 1 && noun.endsWith(QLatin1Char('s')))
        noun.chop(1);
    return noun;
}

QIcon colourSwatch(Colour colour)
{
    QPixmap pixmap(16, 16);
    pixmap.fill(toQColor(colourDisplayRgb(colour)));
    QPainter p(&pixmap);
    p.setPen(QColor(90, 90, 90));
    p.drawRect(0, 0, 15, 15);
    return QIcon(pixmap);
}

QImage maskToQImage(const cv::Mat& mask, QColor colour)
{
    if (mask.empty() || mask.type() != CV_8U)
        return {};
    QImage image(mask.cols, mask.rows, QImage::Format_ARGB32_Premultiplied);
    const QRgb on = qPremultiply(colour.rgba());
    for (int y = 0; y < mask.rows; ++y) {
        const std::uint8_t* m = mask.ptr<std::uint8_t>(y);
        auto* out = reinterpret_cast<QRgb*>(image.scanLine(y));
        for (int x = 0; x < mask.cols; ++x)
            out[x] = m[x] ? on : 0;
    }
    return image;
}

} // namespace fieldsight::ui
