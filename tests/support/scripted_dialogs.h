// Answers for the window's questions in tests (the Dialogs seam): each kind of question takes the
// next queued answer; one asked with none queued is recorded and answered as a cancel, so a test
// never blocks on a modal box and can check what it was asked.
#pragma once

#include "ui/dialogs/dialogs.h"

#include <QStringList>

#include <deque>

namespace fieldsight::test {

class ScriptedDialogs final : public ui::Dialogs
{
public:
    ScriptedDialogs() : m_before(install(this)) {}
    ~ScriptedDialogs() override { install(m_before); }

    std::deque<QString> paths;                       ///< openFile, saveFile, folder
    std::deque<QString> texts;                       ///< text
    std::deque<int> numbers;                         ///< number
    std::deque<QMessageBox::StandardButton> answers; ///< question
    std::deque<int> choices;                         ///< choice (an option's index, -1 cancels)
    QStringList texts_asked; ///< the text of every question and choice, in order
    QStringList asked;       ///< every title, in order
    QStringList unanswered;  ///< titles asked with nothing queued
    QStringList suggested;   ///< the path each file or folder question started from, in order
    QList<int> offered;      ///< the number each number question started from, in order

    QString openFile(QWidget*, const QString& title, const QString& start, const QString&) override
    {
        suggested << start;
        return next(paths, title, QString());
    }
    QString saveFile(QWidget*, const QString& title, const QString& start, const QString&) override
    {
        suggested << start;
        return next(paths, title, QString());
    }
    QString folder(QWidget*, const QString& title, const QString& start) override
    {
        suggested << start;
        return next(paths, title, QString());
    }
    std::optional<QString> text(QWidget*, const QString& title, const QString&,
                                const QString&) override
    {
        asked << title;
        if (texts.empty()) {
            unanswered << title;
            return std::nullopt;
        }
        QString t = texts.front();
        texts.pop_front();
        return t;
    }
    std::optional<int> number(QWidget*, const QString& title, const QString&, int initial, int,
                              int) override
    {
        offered << initial;
        if (numbers.empty())
            return next(numbers, title, std::optional<int>());
        return next(numbers, title, 0);
    }
    QMessageBox::StandardButton question(QWidget*, const QString& title, const QString& text,
                                         QMessageBox::StandardButtons,
                                         QMessageBox::StandardButton) override
    {
        texts_asked << text;
        return next(answers, title, QMessageBox::Cancel);
    }
    int choice(QWidget*, const QString& title, const QString& text, const QStringList&,
               int) override
    {
        texts_asked << text;
        return next(choices, title, -1);
    }
    void information(QWidget*, const QString& title, const QString&) override { asked << title; }

private:
    Dialogs* m_before = nullptr;

    template <class Queue, class Answer>
    Answer next(Queue& queue, const QString& title, Answer none)
    {
        asked << title;
        if (queue.empty()) {
            unanswered << title;
            return none;
        }
        Answer a = queue.front();
        queue.pop_front();
        return a;
    }
};

} // namespace fieldsight::test
