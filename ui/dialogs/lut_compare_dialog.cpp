#include "ui/dialogs/lut_compare_dialog.h"

#include "ui/adapters/image_adapter.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QGridLayout>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace fieldsight::ui {

namespace {

} // namespace

LutCompareDialog::LutCompareDialog(LutDocument& doc, ColourLut other, const QString& other_path,
                                   QWidget* parent)
    : QDialog(parent), m_doc(doc), m_other(std::move(other)),
      m_other_name(QFileInfo(other_path).fileName())
{
    setObjectName(QStringLiteral("lut_compare"));
    setWindowTitle(tr("Compare with %1").arg(m_other_name));
    auto* column = new QVBoxLayout(this);
    m_summary = new QLabel(this);
    m_summary->setWordWrap(true);
    column->addWidget(m_summary);

    m_table = new QTableWidget(0, 3, this);
    m_table->setObjectName(QStringLiteral("compare_table"));
    m_table->setHorizontalHeaderLabels({tr("Here"), tr("In %1").arg(m_other_name), tr("Cells")});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->verticalHeader()->hide();
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    column->addWidget(m_table, 1);
    connect(m_table, &QTableWidget::itemSelectionChanged, this, [this] {
        std::vector<std::uint32_t> cells;
        const auto rows = m_table->selectionModel()->selectedRows();
        if (!rows.isEmpty()) {
            const int row = rows.front().row();
            const auto here = Colour(m_table->item(row, 0)->data(Qt::UserRole).toInt());
            const auto there = Colour(m_table->item(row, 1)->data(Qt::UserRole).toInt());
            for (const CellChange& c : m_diff.cells)
                if (c.before == here && c.after == there)
                    cells.push_back(c.cell);
        }
        emit cellsChosen(cells);
    });

    auto* merge_box = new QGroupBox(tr("Merge into the edited LUT"), this);
    auto* grid = new QGridLayout(merge_box);
    std::array<bool, kColourCount> present{};
    for (std::size_t i = 0; i < ColourLut::kCells; ++i)
        present[m_other.data()[i] % kColourCount] = true;
    int slot = 0;
    for (int c = 1; c < kColourCount; ++c) {
        if (!present[std::size_t(c)])
            continue;
        auto* box = new QCheckBox(colourLabel(Colour(c)), merge_box);
        box->setObjectName(QStringLiteral("merge.%1").arg(colourLabel(Colour(c))));
        box->setIcon(colourSwatch(Colour(c)));
        box->setChecked(true);
        connect(box, &QCheckBox::toggled, this, &LutCompareDialog::refreshPreview);
        grid->addWidget(box, slot / 4, slot % 4);
        m_merge_boxes[Colour(c)] = box;
        ++slot;
    }
    m_keep_others =
        new QCheckBox(tr("Only cells unclassified here (keep conflicts as they are)"), merge_box);
    m_keep_others->setObjectName(QStringLiteral("merge.keep_others"));
    connect(m_keep_others, &QCheckBox::toggled, this, &LutCompareDialog::refreshPreview);
    grid->addWidget(m_keep_others, slot / 4 + 1, 0, 1, 4);
    m_preview = new QLabel(merge_box);
    m_preview->setObjectName(QStringLiteral("merge.preview"));
    m_preview->setWordWrap(true);
    grid->addWidget(m_preview, slot / 4 + 2, 0, 1, 4);
    column->addWidget(merge_box);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    QPushButton* merge_button = buttons->addButton(tr("Merge"), QDialogButtonBox::ActionRole);
    merge_button->setObjectName(QStringLiteral("merge.apply"));
    connect(merge_button, &QPushButton::clicked, this, [this] { merge(); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    column->addWidget(buttons);

    connect(&m_doc, &LutDocument::changed, this, &LutCompareDialog::refresh);
    connect(this, &QDialog::finished, this, [this] { emit cellsChosen({}); });
    refresh();
    resize(520, 560);
}

void LutCompareDialog::refresh()
{
    m_diff = diffLuts(m_doc.table(), m_other);
    m_pairs.clear();
    const auto counts = m_diff.pairCounts();
    for (int a = 0; a < kColourCount; ++a)
        for (int b = 0; b < kColourCount; ++b)
            if (counts[std::size_t(a)][std::size_t(b)] > 0)
                m_pairs[{Colour(a), Colour(b)}] = counts[std::size_t(a)][std::size_t(b)];
    const QSignalBlocker block(m_table);
    m_table->setRowCount(int(m_pairs.size()));
    const QLocale locale;
    int row = 0;
    for (const auto& [pair, cells] : m_pairs) {
        auto* here = new QTableWidgetItem(colourLabel(pair.first));
        here->setData(Qt::UserRole, int(pair.first));
        here->setIcon(colourSwatch(pair.first));
        auto* there = new QTableWidgetItem(colourLabel(pair.second));
        there->setData(Qt::UserRole, int(pair.second));
        auto* count = new QTableWidgetItem(locale.toString(qulonglong(cells)));
        count->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_table->setItem(row, 0, here);
        m_table->setItem(row, 1, there);
        m_table->setItem(row, 2, count);
        ++row;
    }
    m_summary->setText(m_diff.cells.empty()
                           ? tr("The tables are identical.")
                           : tr("%1 of %2 cells differ between the edited LUT and %3, by class "
                                "pair below; choose a row to see its cells in the UV plane and "
                                "their pixels in the image.")
                                 .arg(locale.toString(qulonglong(m_diff.cells.size())),
                                      locale.toString(qulonglong(ColourLut::kCells)),
                                      m_other_name));
    refreshPreview();
}

void LutCompareDialog::setMergeClasses(const std::vector<Colour>& classes)
{
    for (auto& [colour, box] : m_merge_boxes)
        box->setChecked(std::find(classes.begin(), classes.end(), colour) != classes.end());
}

void LutCompareDialog::setMergeKeepsOthers(bool keep)
{
    m_keep_others->setChecked(keep);
}

std::vector<CellChange> LutCompareDialog::plannedMerge() const
{
    std::vector<Colour> classes;
    for (const auto& [colour, box] : m_merge_boxes)
        if (box->isChecked())
            classes.push_back(colour);
    return mergeChanges(m_doc.table(), m_other, classes, m_keep_others->isChecked());
}

QString LutCompareDialog::mergePreview() const
{
    return m_preview->text();
}

void LutCompareDialog::refreshPreview()
{
    const auto changes = plannedMerge();
    const QLocale locale;
    m_preview->setText(changes.empty()
                           ? tr("A merge would change nothing.")
                           : tr("A merge would change %1 cells; %2 of them now "
                                "belong to another class here.")
                                 .arg(locale.toString(qulonglong(changes.size())),
                                      locale.toString(qulonglong(conflictsIn(changes)))));
}

bool LutCompareDialog::merge()
{
    QStringList names;
    for (const auto& [colour, box] : m_merge_boxes)
        if (box->isChecked())
            names << colourLabel(colour);
    return m_doc.edit(tr("Merge %1 from %2").arg(names.join(QStringLiteral(", ")), m_other_name),
                      plannedMerge());
}

} // namespace fieldsight::ui
