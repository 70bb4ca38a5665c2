#include "ui/document/lut_document.h"

#include "ui/adapters/image_adapter.h"
#include "ui/adapters/local_path.h"
#include "ui/recovery/recovery_meta.h"

#include "visioncore/basics/json_text.h"
#include "visioncore/basics/atomic_file.h"
#include "visioncore/io/lut_import.h"
#include "visioncore/services/lut_compare.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QUndoCommand>

#include <nlohmann/json.hpp>

namespace fieldsight::ui {

/// One edit: the cells it changed, with what they were, so undo restores the bytes exactly.
class LutCellsCommand : public QUndoCommand
{
public:
    LutCellsCommand(LutDocument& doc, const QString& text, std::vector<CellChange> changes,
                    int stroke)
        : QUndoCommand(text), m_doc(doc), m_changes(std::move(changes)), m_stroke(stroke)
    {
    }
    void redo() override { m_doc.apply(m_changes, true); }
    void undo() override { m_doc.apply(m_changes, false); }
    int id() const override { return m_stroke > 0 ? 1 : -1; }
    bool mergeWith(const QUndoCommand* other) override
    {
        const auto* next = static_cast<const LutCellsCommand*>(other);
        if (next->m_stroke != m_stroke)
            return false;
        // Applied in order and undone in reverse, repeated cells come back to their first value.
        m_changes.insert(m_changes.end(), next->m_changes.begin(), next->m_changes.end());
        return true;
    }

private:
    LutDocument& m_doc;
    std::vector<CellChange> m_changes;
    int m_stroke;
};

LutDocument::LutDocument(QObject* parent) : Document(Saving::ByUser, parent) {}

void LutDocument::reset(std::shared_ptr<const ColourLut> lut, const QString& path,
                        const std::optional<FileFingerprint>& read)
{
    m_table = lut ? *lut : ColourLut();
    m_version = lut;
    m_saved = std::move(lut);
    setFile(path, read);
    clearHistory();
    m_edit_base.reset();
    resetMerge();
    emit changed();
    emit modifiedChanged(false);
}

void LutDocument::revert()
{
    const DiskState read = disk(); // the file as read: a change since is still one
    reset(m_saved, path());
    setDisk(read);
}

std::shared_ptr<const ColourLut> LutDocument::version() const
{
    if (!m_version)
        m_version = std::make_shared<const ColourLut>(m_table);
    return m_version;
}

bool LutDocument::edit(const QString& text, std::vector<CellChange> changes, int stroke)
{
    if (changes.empty())
        return false;
    // A stroke's later pieces merge into its command: the edit's base stays the stroke's start.
    if (!mergesWithTop(stroke))
        m_edit_base = version();
    m_in_edit = true;
    pushEdit(new LutCellsCommand(*this, text, std::move(changes), stroke), stroke);
    m_in_edit = false;
    return true;
}

std::size_t LutDocument::clearClass(Colour colour)
{
    if (colour == Colour::Unclassified)
        return 0;
    std::vector<CellChange> changes;
    const std::uint8_t* cells = m_table.data();
    for (std::size_t i = 0; i < ColourLut::kCells; ++i)
        if (cells[i] == std::uint8_t(colour))
            changes.push_back({std::uint32_t(i), colour, Colour::Unclassified});
    const std::size_t n = changes.size();
    edit(tr("Clear %1").arg(colourLabel(colour)), std::move(changes));
    return n;
}

ColourShift LutDocument::estimateRetarget(const cv::Mat* frame, std::size_t* samples) const
{
    std::vector<cv::Vec3b> field;
    if (frame)
        for (int y = frame->rows * 2 / 3; y < frame->rows; ++y)
            for (int x = 0; x < frame->cols; ++x)
                field.push_back(frame->at<cv::Vec3b>(y, x));
    if (samples)
        *samples = field.size();
    return estimateShift(m_table, Colour::Green, field);
}

bool LutDocument::retarget(const ColourShift& shift)
{
    return edit(tr("Retarget by Y %1, Cb %2, Cr %3").arg(shift.y).arg(shift.cb).arg(shift.cr),
                shiftChanges(m_table, shift));
}

void LutDocument::apply(const std::vector<CellChange>& changes, bool forwards)
{
    if (!m_in_edit) { // an undo or redo from the stack
        m_edit_base = version();
        endMerge();
    }
    applyChanges(m_table, changes, forwards);
    m_version.reset();
    noteEdit();
    emit changed();
}

QString LutDocument::noFileMessage() const
{
    return QStringLiteral("the LUT has no file yet: use Save As");
}

Status LutDocument::reload()
{
    if (path().isEmpty())
        return Error{"the LUT has no file to reload"};
    // Noted before reading: a write during the read is a change still to be seen.
    DiskState read;
    read.remember(path());
    auto on_disk = importLut(toLocalPath(path()));
    if (!on_disk)
        return on_disk.error();
    edit(tr("Reload LUT from disk"), diffLuts(m_table, on_disk.value()).cells);
    endMerge();
    m_saved = version();
    setDisk(read);
    markClean();
    return {};
}

Status LutDocument::writeFile(const QString& path)
{
    // Only .lut is written; the foreign formats are import-only.
    if (!path.endsWith(QLatin1String(".lut"), Qt::CaseInsensitive))
        return Error{toLocalPath(path) + ": LUTs are saved as .lut (SPEC §3)"};
    if (Status s = m_table.save(toLocalPath(path)); !s)
        return s;
    m_saved = version();
    return {};
}

QString LutDocument::recoveryBase() const
{
    return QDir(recoveryDir()).filePath(QStringLiteral("lut-recovery"));
}

Status LutDocument::writeRecovery()
{
    if (!makeLocalFolder(recoveryDir()))
        return Error{toLocalPath(recoveryDir()) + ": cannot create the recovery folder"};
    const QString base = recoveryBase();
    if (Status s = m_table.save(toLocalPath(base + ".lut")); !s)
        return s;
    nlohmann::ordered_json meta{{"format", "fieldsight-lut-recovery/1"}};
    putPath(meta, "path", path());
    putPath(meta, "stream", m_stream);
    meta["saved_at"] = recoveryTimestamp();
    return writeFileAtomically(toLocalPath(base + ".json"), jsonText(meta, 2) + '\n');
}

std::optional<LutRecovery> LutDocument::findRecovery() const
{
    const QString base = recoveryBase();
    if (!localPathExists(base + ".lut") || !localPathExists(base + ".json"))
        return std::nullopt;
    // Two paths and a time: a megabyte is a damaged or foreign file, not read.
    const Result<std::string> text = readWholeFile(toLocalPath(base + ".json"), 1 << 20);
    if (!text)
        return std::nullopt;
    const auto meta = jsonOrDiscarded(text.value());
    if (!meta.is_object() || stringAt(meta, "format") != "fieldsight-lut-recovery/1")
        return std::nullopt;
    LutRecovery r;
    r.lut_file = base + ".lut";
    r.path = pathAt(meta, "path");
    r.stream = pathAt(meta, "stream");
    r.saved_at = QString::fromStdString(stringAt(meta, "saved_at"));
    return r;
}

Status LutDocument::recover(const LutRecovery& recovery)
{
    auto table = ColourLut::load(toLocalPath(recovery.lut_file));
    if (!table)
        return table.error();
    m_table = std::move(table).value();
    m_version.reset();
    setFile(recovery.path);
    clearHistory();
    setRecovered();
    m_edit_base.reset();
    resetMerge();
    emit changed();
    emit modifiedChanged(true);
    return {};
}

void LutDocument::discardRecovery()
{
    QFile::remove(recoveryBase() + ".lut");
    QFile::remove(recoveryBase() + ".json");
}

} // namespace fieldsight::ui
