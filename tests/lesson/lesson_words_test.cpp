// The lesson UI's words (src/lesson/lesson_words.h): every word in every language, and an
// unknown language falls back to English.
#include "lesson/lesson_words.h"

#include <gtest/gtest.h>

#include <cstring>
#include <iterator>
#include <string>

using namespace raylab;

TEST(LessonWords, EveryWordIsGivenInEveryLanguage) {
    constexpr std::size_t n = sizeof(LessonWords) / sizeof(const char*);
    for (const char* language : kLessonLanguages) {
        const char* words[n];
        std::memcpy(words, &lessonWords(language), sizeof words);   // a struct of n pointers, read as an array
        for (std::size_t i = 0; i < n; ++i) {
            ASSERT_NE(words[i], nullptr) << language << ": word " << i;
            EXPECT_GT(std::strlen(words[i]), 0u) << language << ": word " << i;
        }
    }
    EXPECT_EQ(std::string(lessonWords("nl").goals), "Leerdoelen");
    EXPECT_EQ(std::string(lessonWords("en").notes), "Teacher's notes");
    EXPECT_EQ(&lessonWords("fr"), &lessonWords("en"));
    EXPECT_TRUE(isLessonLanguage("nl"));
    EXPECT_FALSE(isLessonLanguage("NL"));
    EXPECT_EQ(lessonLanguageList(), "en, nl");
}
