// The library's remedies (meromorph_remedy codes in meromorph.h) in a MeshLab user's words: this
// filter's parameters and MeshLab's menus.
//
// In:  a remedy code, or a message with its codes, or a map's causes with their codes.
// Out: the words, "message; remedy", "cause: remedy; cause: remedy".
#pragma once

#include <QString>
#include <vector>

QString meshlab_remedy_words(int remedy);
QString with_meshlab_remedies(const QString &message, const std::vector<int> &remedies);
QString meshlab_advice_words(const std::vector<QString> &causes, const std::vector<int> &remedies);
