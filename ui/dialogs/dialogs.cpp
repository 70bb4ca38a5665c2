#include "ui/dialogs/dialogs.h"

#include <QFileDialog>
#include <QInputDialog>
#include <QPushButton>

#include <algorithm>
#include <vector>

#include <utility>

namespace fieldsight::ui {

namespace {

/// Qt's modal dialogs.
class QtDialogs final : public Dialogs
{
public:
    QString openFile(QWidget* parent, const QString& title, const QString& dir,
                     const QString& filter) override
    {
        return QFileDialog::getOpenFileName(parent, title, dir, filter);
    }
    QString saveFile(QWidget* parent, const QString& title, const QString& suggestion,
                     const QString& filter) override
    {
        return QFileDialog::getSaveFileName(parent, title, suggestion, filter);
    }
    QString folder(QWidget* parent, const QString& title, const QString& dir) override
    {
        return QFileDialog::getExistingDirectory(parent, title, dir);
    }
    std::optional<QString> text(QWidget* parent, const QString& title, const QString& label,
                                const QString& initial) override
    {
        bool ok = false;
        const QString t =
            QInputDialog::getText(parent, title, label, QLineEdit::Normal, initial, &ok);
        return ok ? std::optional<QString>(t) : std::nullopt;
    }
    std::optional<int> number(QWidget* parent, const QString& title, const QString& label,
                              int initial, int min, int max) override
    {
        bool ok = false;
        const int n = QInputDialog::getInt(parent, title, label, initial, min, max, 1, &ok);
        return ok ? std::optional<int>(n) : std::nullopt;
    }
    QMessageBox::StandardButton question(QWidget* parent, const QString& title, const QString& text,
                                         QMessageBox::StandardButtons buttons,
                                         QMessageBox::StandardButton preferred) override
    {
        return QMessageBox::question(parent, title, text, buttons, preferred);
    }
    void information(QWidget* parent, const QString& title, const QString& text) override
    {
        QMessageBox::information(parent, title, text);
    }
    int choice(QWidget* parent, const QString& title, const QString& text,
               const QStringList& options, int preferred) override
    {
        QMessageBox box(QMessageBox::Question, title, text, QMessageBox::NoButton, parent);
        std::vector<QAbstractButton*> buttons;
        for (int i = 0; i < options.size(); ++i) {
            QPushButton* b = box.addButton(options[i], QMessageBox::AcceptRole);
            buttons.push_back(b);
            if (i == preferred)
                box.setDefaultButton(b);
        }
        box.addButton(QMessageBox::Cancel);
        box.exec();
        const auto it = std::find(buttons.begin(), buttons.end(), box.clickedButton());
        return it == buttons.end() ? -1 : int(it - buttons.begin());
    }
};

QtDialogs g_qt_dialogs;
Dialogs* g_installed = nullptr;

} // namespace

Dialogs& Dialogs::current()
{
    return g_installed ? *g_installed : g_qt_dialogs;
}

Dialogs* Dialogs::install(Dialogs* dialogs)
{
    return std::exchange(g_installed, dialogs);
}

} // namespace fieldsight::ui
