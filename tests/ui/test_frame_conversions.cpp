// The per-frame colour conversions of the read path (issue 33, frames of any size): the same
// pixels as OpenCV's conversions with a channel swap, and no frame-sized buffer in between (each
// costs a 1280x720 frame about a millisecond of fresh pages and another pass).
#include "support/test_suite.h"
#include "ui/adapters/image_adapter.h"
#include "visioncore/basics/ycbcr.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <QImage>
#include <QtTest>

#include <cstddef>
#include <cstdint>

using namespace fieldsight;

namespace {

/// Counts the pixel buffers of at least `min_bytes` that cv::Mat allocates while it is the
/// default allocator (headers over existing data are not counted).
class CountingMatAllocator final : public cv::MatAllocator
{
public:
    explicit CountingMatAllocator(std::size_t min_bytes)
        : m_std(cv::Mat::getStdAllocator()), m_min_bytes(min_bytes)
    {
    }
    cv::UMatData* allocate(int dims, const int* sizes, int type, void* data, std::size_t* step,
                           cv::AccessFlag flags, cv::UMatUsageFlags usage) const override
    {
        std::size_t bytes = CV_ELEM_SIZE(type);
        for (int i = 0; i < dims; ++i)
            bytes *= std::size_t(sizes[i]);
        if (!data && bytes >= m_min_bytes)
            ++large;
        return m_std->allocate(dims, sizes, type, data, step, flags, usage);
    }
    bool allocate(cv::UMatData* data, cv::AccessFlag flags, cv::UMatUsageFlags usage) const override
    {
        return m_std->allocate(data, flags, usage);
    }
    void deallocate(cv::UMatData* data) const override { m_std->deallocate(data); }

    mutable int large = 0;

private:
    cv::MatAllocator* m_std;
    std::size_t m_min_bytes;
};

/// Frame-sized buffers allocated while `work` runs (a quarter of `frame`'s bytes or more).
template <typename Work> int frameBuffersDuring(const cv::Mat& frame, Work work)
{
    CountingMatAllocator counting(frame.total() * frame.elemSize() / 4);
    cv::MatAllocator* before = cv::Mat::getDefaultAllocator();
    cv::Mat::setDefaultAllocator(&counting);
    work();
    cv::Mat::setDefaultAllocator(before);
    return counting.large;
}

cv::Mat randomFrameForConversions(int width, int height, int seed)
{
    cv::Mat image(height, width, CV_8UC3);
    cv::RNG rng{std::uint64_t(seed)};
    rng.fill(image, cv::RNG::UNIFORM, 0, 256);
    return image;
}

/// The conversions as they were: OpenCV's YCrCb with the chroma channels swapped by mixChannels.
cv::Mat swappedChroma(const cv::Mat& in)
{
    cv::Mat out(in.size(), CV_8UC3);
    const int from_to[] = {0, 0, 1, 2, 2, 1};
    cv::mixChannels(&in, 1, &out, 1, from_to, 3);
    return out;
}

cv::Mat referenceYcbcr(const cv::Mat& bgr)
{
    cv::Mat ycrcb;
    cv::cvtColor(bgr, ycrcb, cv::COLOR_BGR2YCrCb);
    return swappedChroma(ycrcb);
}

cv::Mat referenceBgr(const cv::Mat& ycbcr)
{
    cv::Mat bgr;
    cv::cvtColor(swappedChroma(ycbcr), bgr, cv::COLOR_YCrCb2BGR);
    return bgr;
}

bool samePixels(const cv::Mat& a, const cv::Mat& b)
{
    return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

} // namespace

class TestFrameConversions : public QObject
{
    Q_OBJECT

private slots:
    void sameAsOpenCvWithSwappedChroma_data()
    {
        QTest::addColumn<int>("width");
        QTest::addColumn<int>("height");
        QTest::newRow("1x1") << 1 << 1;
        QTest::newRow("bands and a remainder") << 37 << 53;
        QTest::newRow("320x240") << 320 << 240;
        QTest::newRow("1280x720") << 1280 << 720;
    }
    void sameAsOpenCvWithSwappedChroma()
    {
        QFETCH(int, width);
        QFETCH(int, height);
        const cv::Mat bgr = randomFrameForConversions(width, height, width * height);
        const cv::Mat ycbcr = bgrToYcbcr(bgr);
        QVERIFY(samePixels(ycbcr, referenceYcbcr(bgr)));
        QVERIFY(samePixels(ycbcrToBgr(ycbcr), referenceBgr(ycbcr)));
        cv::Mat bgra(ycbcr.size(), CV_8UC4, cv::Scalar::all(7));
        ycbcrToBgra(ycbcr, bgra);
        cv::Mat reference_bgra;
        cv::cvtColor(referenceBgr(ycbcr), reference_bgra, cv::COLOR_BGR2BGRA);
        QVERIFY(samePixels(bgra, reference_bgra));
        // The display's raw image, at 1:1 and zoomed.
        for (const int scale : {1, 3}) {
            const QImage raw = ui::ycbcrToZoomedQImage(ycbcr, scale);
            QCOMPARE(raw.format(), QImage::Format_RGB32);
            cv::Mat zoomed;
            cv::resize(reference_bgra, zoomed, cv::Size(width * scale, height * scale), 0, 0,
                       cv::INTER_NEAREST);
            const cv::Mat view(raw.height(), raw.width(), CV_8UC4, const_cast<uchar*>(raw.bits()),
                               std::size_t(raw.bytesPerLine()));
            QVERIFY(samePixels(view, zoomed));
        }
    }

    void partOfALargerImage()
    {
        // A region of interest: rows that are not contiguous, in and out.
        const cv::Mat big = randomFrameForConversions(90, 70, 5);
        const cv::Mat bgr = big(cv::Rect(3, 4, 41, 33));
        const cv::Mat ycbcr = bgrToYcbcr(bgr);
        QVERIFY(samePixels(ycbcr, referenceYcbcr(bgr)));
        const cv::Mat ycbcr_part = randomFrameForConversions(90, 70, 6)(cv::Rect(5, 1, 41, 33));
        cv::Mat bgra_big(70, 90, CV_8UC4, cv::Scalar::all(9));
        cv::Mat bgra = bgra_big(cv::Rect(2, 2, 41, 33));
        ycbcrToBgra(ycbcr_part, bgra);
        cv::Mat reference_bgra;
        cv::cvtColor(referenceBgr(ycbcr_part), reference_bgra, cv::COLOR_BGR2BGRA);
        QVERIFY(samePixels(bgra, reference_bgra));
        QCOMPARE(bgra_big.at<cv::Vec4b>(0, 0), cv::Vec4b(9, 9, 9, 9)); // nothing outside it
    }

    void noFrameSizedBufferInBetween()
    {
        const cv::Mat bgr = randomFrameForConversions(1280, 720, 11);
        cv::Mat ycbcr;
        // The result only (it was the conversion's and then the swap's).
        QCOMPARE(frameBuffersDuring(bgr, [&] { ycbcr = bgrToYcbcr(bgr); }), 1);
        cv::Mat bgra(ycbcr.size(), CV_8UC4);
        const uchar* pixels = bgra.data;
        // Straight into the buffer given, through a band of rows.
        QCOMPARE(frameBuffersDuring(bgr, [&] { ycbcrToBgra(ycbcr, bgra); }), 0);
        QCOMPARE(bgra.data, pixels);
        // The raw image at 1:1 is written straight into the QImage (it was swapped, converted
        // to BGR, then to BGRA: two frame-sized buffers).
        QImage raw;
        QCOMPARE(frameBuffersDuring(bgr, [&] { raw = ui::ycbcrToZoomedQImage(ycbcr, 1); }), 0);
        QCOMPARE(raw.size(), QSize(1280, 720));
    }
};

FIELDSIGHT_TEST_SUITE(TestFrameConversions, Core)
#include "test_frame_conversions.moc"
